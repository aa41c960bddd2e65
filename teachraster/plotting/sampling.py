"""Prefilter, sample, reconstruct: antialiasing and mipmapping as one idea, on a 1-D signal.

A pixel (lesson 08) and a texture read (lesson 09) both *sample* a signal: the triangle's
coverage, or the texture seen through the perspective map. Sampling a frequency above half the
sampling rate (the Nyquist limit) folds it down into a false low frequency: aliasing (jaggies,
crawling edges, moiré). The cure is always the same three steps:

1. **prefilter**: blur the signal so that nothing above the Nyquist limit is left (a pixel's
   area coverage is a box prefilter; a mip level is the texture box-filtered in advance);
2. **sample** it at the rate you have (one value per pixel, or per sample of MSAA);
3. **reconstruct** between the samples (the display's pixels; bilinear filtering's tent).

The signal here is a chirp, ``cos`` of a phase whose frequency rises from 2 to 60 cycles per
unit along x, like a checkerboard receding to the horizon. A box is not an ideal prefilter:
its response, sinc(f / rate) for a box one sample wide, has a main lobe reaching up to the
sampling rate (0.64 still at the Nyquist limit) and side lobes beyond, so some of what lies
above the Nyquist limit gets through and still aliases; a wider, smooth (Gaussian) filter
removes more and blurs more.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .style import COLORS, OKABE_ITO

#: Frequencies of the chirp (cycles per unit) at x = 0 and x = 1.
CHIRP = (2.0, 60.0)
#: Points of the fine grid the continuous signal is drawn and filtered on.
FINE = 4096
#: The prefilters offered.
KERNELS = ("box", "gaussian")


def chirp(x):
    """The signal: 0.5 + 0.5 cos(2π φ(x)), local frequency rising linearly along :data:`CHIRP`."""
    f0, f1 = CHIRP
    return 0.5 + 0.5 * np.cos(2 * np.pi * (f0 * x + 0.5 * (f1 - f0) * x**2))


def local_frequency(x):
    """Cycles per unit of the chirp at ``x``."""
    f0, f1 = CHIRP
    return f0 + (f1 - f0) * np.asarray(x, dtype=float)


def prefilter(values, spacing: float, width: float, kernel: str = "box"):
    """Convolve fine-grid ``values`` (grid step 1/FINE) with a kernel ``width`` samples wide.

    ``width`` is in sample spacings (1 = one pixel's box); 0 means no prefilter. The Gaussian
    has standard deviation ``width / 2`` spacings. Edges are padded by mirroring the values:
    the chirp goes on at its local frequency, so a wide filter averages it to its mean there
    too (padding with the end value bent the filtered curve towards that value).
    """
    if kernel not in KERNELS:
        raise ValueError(f"kernel must be one of {KERNELS}, got {kernel!r}")
    if width <= 0:
        return np.asarray(values, dtype=float)
    step = 1.0 / FINE
    if kernel == "box":
        half = max(1, int(round(width * spacing / step / 2)))
        k = np.ones(2 * half + 1)
    else:
        sigma = width * spacing / 2 / step
        half = int(np.ceil(4 * sigma))
        k = np.exp(-0.5 * (np.arange(-half, half + 1) / sigma) ** 2)
    k /= k.sum()
    padded = np.pad(values, half, mode="symmetric")
    return np.convolve(padded, k, mode="valid")


@dataclass(frozen=True)
class SamplingResult:
    """One run of the three steps: the arrays every panel draws, and the errors."""

    x: np.ndarray  # fine grid
    signal: np.ndarray
    filtered: np.ndarray
    sample_x: np.ndarray
    samples: np.ndarray
    reconstructed: np.ndarray  # on the fine grid (linear interpolation, a tent)
    ideal: np.ndarray  # what an ideal low-pass would keep: the signal below Nyquist, else 0.5
    nyquist: float
    alias_from: float  # x beyond which the signal is above the Nyquist limit
    rms_error: float  # reconstruction against the ideal, over the whole signal
    width: float = 0.0  # the prefilter's width, in sample spacings (0: none)
    kernel: str = "box"  # the prefilter's shape: "box", or "gaussian" (sigma = width / 2)


def sample_signal(rate: int, width: float, kernel: str = "box") -> SamplingResult:
    """Prefilter the chirp, take ``rate`` samples per unit (at cell centres), reconstruct.

    >>> r = sample_signal(32, 0.0)
    >>> r.nyquist, round(r.alias_from, 3)
    (16.0, 0.241)
    >>> sample_signal(32, 2.0, "gaussian").rms_error < r.rms_error
    True
    """
    rate = int(rate)
    if rate < 2:
        raise ValueError(f"rate must be >= 2 samples per unit, got {rate}")
    x = (np.arange(FINE) + 0.5) / FINE
    signal = chirp(x)
    spacing = 1.0 / rate
    filtered = prefilter(signal, spacing, float(width), kernel)
    sample_x = (np.arange(rate) + 0.5) * spacing
    samples = np.interp(sample_x, x, filtered)
    reconstructed = np.interp(x, sample_x, samples)
    nyquist = rate / 2
    ideal = np.where(local_frequency(x) < nyquist, signal, 0.5)
    f0, f1 = CHIRP
    alias_from = float(np.clip((nyquist - f0) / (f1 - f0), 0.0, 1.0))
    rms = float(np.sqrt(np.mean((reconstructed - ideal) ** 2)))
    return SamplingResult(x, signal, filtered, sample_x, samples, reconstructed, ideal,
                          float(nyquist), alias_from, rms, float(width), kernel)  # fmt: skip


def prefiltered_key(width: float, kernel: str = "box") -> str:
    """The key of the prefiltered line at filter ``width`` and shape ``kernel``: the signal
    itself at 0, else the filter named, a box (a local average) or a Gaussian with its
    sigma (``width / 2``: the width is 2 sigma). Its first line, the longest, has the same
    length at every width (digits are equally wide), so the key's box keeps its size
    (review r101 08-D: a key that changed size left a stale sliver in the page's picture;
    review r119 08-C: a key that said "at width 0: the signal" at every width was stale at
    every other width; review r129 08-7: the key named neither shape)."""
    if width <= 0:
        named = "(none: the signal)"
    elif kernel == "gaussian":
        named = f"(Gaussian, σ = {width / 2:.2f})"
    else:
        named = "(box: a local average)"
    return f"prefiltered, width {width:.2f}\n{named}"


@dataclass
class SamplingArtists:
    """The lines :func:`plot_sampling` drew, updated in place by :func:`update_sampling`."""

    signal: object
    filtered: object
    stems: object
    reconstructed: object
    ideal: object
    spans: list
    #: the prefiltered signal again, faint, under the samples (panel 2)
    filtered_faint: object = None


def plot_sampling(axes, result: SamplingResult) -> SamplingArtists:
    """Three stacked panels: prefilter, sample, reconstruct. ``axes`` is a sequence of 3 Axes."""
    a, b, c = axes
    (sig,) = a.plot(result.x, result.signal, color="#BBBBBB", lw=1, label="signal")
    (filt,) = a.plot(result.x, result.filtered, color=OKABE_ITO["blue"], lw=2,
                     label="prefiltered")  # fmt: skip
    a.set_title("1. prefilter")
    stems = b.plot(result.sample_x, result.samples, "o", color=COLORS["outside"], ms=6,
                   label="samples")[0]  # fmt: skip
    (faint,) = b.plot(result.x, result.filtered, color=OKABE_ITO["blue"], lw=1, alpha=0.35,
                      label="prefiltered (faint)")  # fmt: skip
    b.set_title("2. sample")
    # dashed and darker: in a shared key it must not look like the signal's grey line
    (ideal,) = c.plot(result.x, result.ideal, color="0.3", lw=1.5, ls="--",
                      label="ideal (nothing above Nyquist)")  # fmt: skip
    (rec,) = c.plot(result.x, result.reconstructed, color=OKABE_ITO["bluish_green"], lw=2.5,
                    label="reconstructed: linear,\nas bilinear filtering")  # fmt: skip
    # short: a title wider than the panel lost its "3." off the figure's left edge (r61 08-3)
    c.set_title("3. reconstruct")
    c.set_xlabel("x (the frequency rises to the right)")
    spans = []
    for ax in axes:
        ax.set(xlim=(0, 1), ylim=(-0.08, 1.08), yticks=[0, 1])
        spans.append(ax.axvspan(result.alias_from, 1, color=OKABE_ITO["yellow"], alpha=0.25,
                                lw=0))  # fmt: skip
    # keys beside the panels, not in them: inside, at the lower left, they hid the signal's
    # troughs and the reconstruction's dips the student compares with the ideal (review r42)
    for ax in axes:  # panel 2 too: its dots and its faint line are named (review r133 08-F)
        ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=12, frameon=False)
    art = SamplingArtists(sig, filt, stems, rec, ideal, spans, faint)
    _name_prefiltered(art, result)
    return art


def _name_prefiltered(art: SamplingArtists, result: SamplingResult) -> None:
    """The key of the "prefiltered" line says what it is at the current width: at 0 the signal
    itself, not a second curve (:func:`prefiltered_key`)."""
    legend = art.filtered.axes.get_legend()
    if legend is None:
        return
    legend.get_texts()[1].set_text(prefiltered_key(result.width, result.kernel))


def update_sampling(art: SamplingArtists, result: SamplingResult) -> None:
    """Move every line of ``art`` to ``result`` (the figure is not redrawn here)."""
    art.filtered.set_ydata(result.filtered)
    if art.filtered_faint is not None:  # it stayed at the first filter (found 2 Dec 2026)
        art.filtered_faint.set_ydata(result.filtered)
    art.stems.set_data(result.sample_x, result.samples)
    art.reconstructed.set_ydata(result.reconstructed)
    art.ideal.set_ydata(result.ideal)
    _name_prefiltered(art, result)
    for span in art.spans:  # a Rectangle in axes-fraction y (matplotlib >= 3.9)
        span.set_x(result.alias_from)
        span.set_width(1.0 - result.alias_from)
