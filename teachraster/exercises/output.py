"""What a student's function prints during a check: kept aside, capped, shown once afterwards.

A debug ``print`` left in a function runs on every case: ten thousand lines through a Jupyter
kernel take longer than the function itself, and would bury the report. While a check runs,
:func:`captured` replaces ``sys.stdout`` and ``sys.stderr`` by a :class:`Capture` that keeps the
first ``KEEP`` lines written from the checking threads (the thread calling ``check`` and the
threads running its cases), counts the rest, and passes every other thread's output through.
Afterwards :meth:`Capture.summary` says how much was printed and :meth:`Capture.replay` writes
the lines kept, under a heading, to the real output. Past the first ``KEEP`` lines a ``print``
of the checking threads is counted without formatting its arguments (a line per call, plus the
line breaks of its ``str`` arguments): formatting ten thousand arrays took more CPU than the
function itself, and printing must not count against the student (r122 D3-2). A warning (numpy's "overflow encountered
in divide") raised in the checking threads is counted apart, by its text, and said as a
warning, never as something the function printed (r39 03-2).

>>> import sys
>>> with captured() as out:
...     for k in range(500):
...         print("x =", k)
>>> out.lines, out.kept[:2]
(500, ['x = 0', 'x = 1'])
"""

from __future__ import annotations

import builtins
import sys
import threading
import warnings
from contextlib import contextmanager

#: Lines kept (and shown after the check); the others are counted only.
KEEP = 20
#: Characters kept of one line.
WIDTH = 200


class Capture:
    """Output of the checking threads, capped; :attr:`lines` counts every line written."""

    def __init__(self):
        self.kept: list[str] = []
        self.lines = 0
        self.warned: dict[str, int] = {}  # each warning's text: how often
        self._partial = ""
        self._threads = {threading.get_ident()}
        self._lock = threading.Lock()

    def adopt(self, thread_id: int) -> None:
        """Capture what thread ``thread_id`` writes too (a thread running a case)."""
        self._threads.add(thread_id)

    def owns(self) -> bool:
        return threading.get_ident() in self._threads

    def write(self, text: str) -> None:
        with self._lock:
            if len(self.kept) >= KEEP:  # the cap reached: count lines, keep nothing
                self.lines += text.count("\n")
                return
            text = self._partial + text
            *done, self._partial = text.split("\n")
            self._partial = self._partial[: WIDTH * 4]
            self.lines += len(done)
            room = KEEP - len(self.kept)
            self.kept += [line[:WIDTH] for line in done[:room]]

    def full(self) -> bool:
        """The cap is reached: further lines are counted only."""
        return len(self.kept) >= KEEP

    def count_call(self, args, sep, end) -> None:
        """Count the lines of a ``print`` call past the cap without formatting ``args``."""
        texts = [a for a in (*args, sep, end) if isinstance(a, str)]
        with self._lock:
            self.lines += sum(t.count("\n") for t in texts)

    def warn(self, text: str) -> None:
        """Count one warning (its category and message), apart from the printed lines."""
        with self._lock:
            if text in self.warned or len(self.warned) < KEEP:
                self.warned[text[:WIDTH]] = self.warned.get(text[:WIDTH], 0) + 1

    def finish(self) -> None:
        if self._partial:
            self.write("\n")

    def summary(self) -> str | None:
        """A sentence for the report, or None when nothing was printed nor warned."""
        said = []
        if self.warned:
            n = sum(self.warned.values())
            texts = "; ".join(self.warned)
            said.append(f"your code raised {n} warning{'s' * (n != 1)} during the check "
                        f"({texts}): not a print of yours, {_warned_words(self.warned)}")  # fmt: skip
        if self.lines:
            shown = min(self.lines, len(self.kept))
            # r84 03-3: written when the check returns, so above a report printed after it
            rest = (f"; the first {shown} were shown when the check ended, above this report"
                    if shown else "")  # fmt: skip
            said.append(
                f"your function printed {self.lines} line{'s' * (self.lines != 1)} during the "
                f"check{rest} (printing is slow in a notebook: remove debug prints once done)"
            )
        return "; and ".join(said) or None

    def replay(self, stream) -> None:
        """Write the lines kept to ``stream``, under a heading."""
        if not self.kept:
            return
        more = self.lines - len(self.kept)
        stream.write(
            f"--- your function printed (first {len(self.kept)} of {self.lines} lines) ---\n"
        )
        stream.write("\n".join(self.kept) + "\n")
        if more > 0:
            stream.write(f"--- ... and {more} more lines, not shown ---\n")


#: What a warning of each category tells, as the report says it (r371 C1: a numpy
#: DeprecationWarning from np.cross on 2-vectors was told "an operation that overflowed").
WARNING_WORDS = {
    "RuntimeWarning": "numpy telling of an operation that overflowed, divided by zero or "
    "had no valid answer",
    "DeprecationWarning": "a library telling that something your code calls will change or "
    "go away in a later version (the answer is not affected now)",
}


def _warned_words(warned) -> str:
    """What the warnings caught tell, by their categories (``"Category: message"`` keys)."""
    kinds = dict.fromkeys(text.split(":", 1)[0] for text in warned)
    said = [WARNING_WORDS.get(kind, f"a {kind} from a library your code calls") for kind in kinds]
    return "; ".join(said)


class _Stream:
    """``sys.stdout`` or ``sys.stderr`` during a check: the checking threads' text is captured,
    other threads' goes where it went before."""

    def __init__(self, capture: Capture, original):
        self._capture = capture
        self._original = original

    def write(self, text) -> int:
        if not self._capture.owns():
            return self._original.write(text)
        self._capture.write(str(text))
        return len(text)

    def writelines(self, lines) -> None:
        for line in lines:
            self.write(line)

    def flush(self) -> None:
        if not self._capture.owns():
            self._original.flush()

    def isatty(self) -> bool:
        return False

    def __getattr__(self, name):  # encoding, fileno, ... as the original stream has them
        return getattr(self._original, name)


_state = threading.local()


def current() -> Capture | None:
    """The capture of the check running in this thread, if any."""
    return getattr(_state, "capture", None)


@contextmanager
def captured():
    """Capture the output of the checking threads while the block runs (nested: the outer
    capture keeps it)."""
    outer = current()
    if outer is not None:
        yield outer
        return
    capture = Capture()
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = _Stream(capture, out), _Stream(capture, err)
    shown = warnings.showwarning

    def showwarning(message, category, filename, lineno, file=None, line=None):
        if file is None and capture.owns():
            capture.warn(f"{category.__name__}: {message}")
        else:
            shown(message, category, filename, lineno, file, line)

    warnings.showwarning = showwarning
    printed = builtins.print

    def quiet_print(*args, sep=" ", end="\n", file=None, flush=False):
        ours = file is None or file is sys.stdout or file is sys.stderr
        if ours and capture.owns() and capture.full():
            capture.count_call(args, sep, end)
            return None
        return printed(*args, sep=sep, end=end, file=file, flush=flush)

    builtins.print = quiet_print
    _state.capture = capture
    try:
        yield capture
    finally:
        if builtins.print is quiet_print:
            builtins.print = printed
        if warnings.showwarning is showwarning:
            warnings.showwarning = shown
        _state.capture = None
        if isinstance(sys.stdout, _Stream) and sys.stdout._capture is capture:
            sys.stdout = out
        if isinstance(sys.stderr, _Stream) and sys.stderr._capture is capture:
            sys.stderr = err
        capture.finish()
