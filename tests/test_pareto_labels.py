"""The Pareto chart keeps its labels apart (lesson 06's depth chart had two on top of each other)."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from teachraster.plotting.pareto import LABEL_SPOTS, plot_pareto, spread_labels  # noqa: E402


def test_labels_of_close_points_take_different_spots():
    rows = [
        {"variant": "linear unorm16", "bits": 16, "error": 2900.0},
        {"variant": "window unorm16", "bits": 16, "error": 2500.0},
        {"variant": "window float64", "bits": 53, "error": 0.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "bits", logx=False)
    a, b = (art.labels[v].get_position() for v in ("linear unorm16", "window unorm16"))
    assert a != b  # the second label moved to another spot beside its point
    # a linear cost axis ends near the data (it ran to 3x the largest cost)
    assert ax.get_xlim()[1] < 53 * 1.7
    plt.close(fig)


def test_a_lone_label_keeps_the_first_spot():
    fig, ax = plt.subplots()
    ax.plot([1.0], [1.0])
    label = ax.annotate("alone", (1.0, 1.0), textcoords="offset points", xytext=(0, 0))
    spread_labels(ax, [label])
    sx, sy = LABEL_SPOTS[0]
    x, y = label.get_position()
    assert x * sx > 0 and y * sy > 0  # up and to the right
    plt.close(fig)


def test_a_front_point_is_drawn_above_the_points_it_beats():
    # lesson 06's edge chart: the one-point front sat under grey points at the same place
    rows = [
        {"variant": "front", "cycles": 3.0, "error": 0.0},
        {"variant": "worse", "cycles": 3.0, "error": 1.0},
        {"variant": "dearer", "cycles": 27.0, "error": 0.0},
    ]
    fig, ax = plt.subplots()
    art = plot_pareto(ax, rows, "cycles", logx=False)
    assert art.points["front"].get_zorder() > art.points["dearer"].get_zorder()
    assert [r["variant"] for r in art.front] == ["front"]
    plt.close(fig)


def test_no_error_tick_is_labelled_at_or_below_the_exact_floor():
    """Review r3 06-4: on a log axis the "0 (exact)" floor stands for zero; a tick labelled 20
    under a floor drawn at 45 read as fewer wrong pixels than exact."""
    from matplotlib.ticker import FormatStrFormatter, LogLocator

    from teachraster.plotting.pareto import floor_ticks

    rows = [
        {"variant": "exact", "bits": 64, "error": 0.0},
        {"variant": "coarse", "bits": 16, "error": 450.0},
        {"variant": "fine", "bits": 24, "error": 3000.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "bits", logx=False)
    ax.yaxis.set_major_locator(LogLocator(subs=(1, 2, 5)))
    floor_ticks(ax, art.floor, FormatStrFormatter("%g"))
    fig.canvas.draw()
    labelled = [float(t.get_text()) for t in ax.get_yticklabels() if t.get_text()]
    assert labelled and min(labelled) > 2 * art.floor
    # review r6, 06-2: no major (decade) tick left bare between the floor and its first label
    lo, hi = ax.get_ylim()
    shown = [y for y in ax.yaxis.get_majorticklocs() if lo <= y <= hi]
    assert shown and min(shown) > 2 * art.floor
    plt.close(fig)


def test_no_bare_decade_tick_above_the_floor_with_the_default_locator():
    """Review r6, 06-2: with the floor at 0.7, the decade 10^0 sat above it unlabelled."""
    rows = [
        {"variant": "exact", "cycles": 6, "error": 0.0},
        {"variant": "a", "cycles": 3, "error": 7.0},
        {"variant": "b", "cycles": 2, "error": 200.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    art = plot_pareto(ax, rows, "cycles")
    fig.canvas.draw()
    lo, hi = ax.get_ylim()
    locs, labels = ax.yaxis.get_majorticklocs(), ax.get_yticklabels()
    ticks = [(y, t.get_text()) for y, t in zip(locs, labels) if lo <= y <= hi]
    assert art.floor < 1.0 < 2 * art.floor and ticks
    assert all(text for _, text in ticks), ticks
    plt.close(fig)


def test_the_floor_keeps_a_log_axis_from_labelling_every_minor_tick():
    """Wrapping the formatters must keep the log formatter's choice of labelled minor ticks
    (a first version labelled 2x10^1 ... 9x10^2 over three decades, one on top of another)."""
    rows = [
        {"variant": "exact", "cycles": 3, "error": 0.0},
        {"variant": "a", "cycles": 27, "error": 50.0},
        {"variant": "b", "cycles": 3, "error": 470.0},
    ]
    fig, ax = plt.subplots(figsize=(9, 5))
    plot_pareto(ax, rows, "cycles", logx=False)
    fig.canvas.draw()
    labelled = [t for t in ax.get_yticklabels(minor=True) if t.get_text()]
    assert len(labelled) <= 2
    plt.close(fig)
