"""Is the student's answer the package's own? (``from teachraster import edge_function``)

The package computes every exercise's answer; a student may hand it in as their own: the
function itself (``edge_function = tr.edge_function``), or a wrapper that calls it
(``return tr.mip_level(ddx, ddy, size)``). Each :class:`~.exercise.Exercise` lists the
package functions that are its answer (:class:`~.exercise.PackageAnswer`; the same
``tr.sample`` is bilinear's answer only with ``filter="bilinear"``). Package functions that
are *tools* for an exercise (``edge_function`` inside ``barycentric``) are not listed, so they
are free to use.

How a call is seen: while the student's cases run, :func:`watching` swaps the code of each
listed function (``function.__code__``) for a stub that notes the call and runs the original.
Every reference to the function runs the stub, in any thread: one taken before the check
(``line = tr.rasterize_line``), one handed to a thread pool made before it
(``pool.submit(tr.rasterize_line, ...)``). r11 09-B2: a profile hook (``sys.setprofile``)
sees the calls of its own thread only, and ``threading.setprofile`` threads started after it,
so a worker thread's call passed unflagged. The check's own calls (its expected answers, its
judging) run outside the window.
"""

from __future__ import annotations

import inspect
import threading
import types
from contextlib import contextmanager

from .exercise import Exercise, PackageAnswer

#: The windows open now (a check inside a student's function opens a second one): each a
#: (listed answers by function, the answers seen called). A tuple, replaced whole, so that a
#: stub reads it without a lock.
_OPEN: tuple = ()
#: function -> [its own code, its kwdefaults, how many windows watch it]
_SWAPPED: dict = {}
_LOCK = threading.Lock()


def _function(answer: PackageAnswer):
    """The Python function whose code runs when ``answer`` is called (None: not Python)."""
    f = inspect.unwrap(answer.function)
    return f if isinstance(f, types.FunctionType) else None


def _name(answer: PackageAnswer) -> str:
    f = inspect.unwrap(answer.function)
    return f"teachraster's {getattr(f, '__qualname__', getattr(f, '__name__', 'function'))}"


def _words(spec: Exercise, answer: PackageAnswer, how: str) -> str:
    if answer.words is not None:  # a checker's private function (exercise 11)
        return f"your {spec.name} {how} {_name(answer)}: {answer.words}"
    return (
        f"your {spec.name} {how} {_name(answer)}, which computes {answer.what}: the check "
        "does not count the package's own function as your work. Write the computation "
        "yourself (the package's function is there to compare with, not to hand in)"
    )


def _matches(answer: PackageAnswer, original, args, kwargs) -> bool:
    if answer.when is None:
        return True
    try:
        bound = inspect.signature(original).bind(*args, **kwargs)
    except TypeError:  # a call the function itself refuses
        return False
    bound.apply_defaults()
    return bool(answer.when(dict(bound.arguments)))


def _noted(f, original, args, kwargs) -> None:
    """Note a call of ``f`` in every open window that lists it (and whose ``when`` fits)."""
    for listed, seen in _OPEN:
        for answer in listed.get(f, ()):
            if answer not in seen and _matches(answer, original, args, kwargs):
                seen.append(answer)


def _stub_code(f):
    """A code object ``(*args, _watch_, **kwargs)`` that calls ``_watch_(args, kwargs)``, with
    as many free variables as ``f`` has (a function's code can only be swapped for one with
    as many), named as ``f``'s code for the tracebacks."""
    free = [f"_free{k}" for k in range(len(f.__code__.co_freevars))]
    lines = ["def _outer():", *(f"    {n} = None" for n in free),
             "    def stub(*args, _watch_=None, **kwargs):",
             *([f"        {', '.join(free)}"] if free else []),
             "        return _watch_(args, kwargs)",
             "    return stub"]  # fmt: skip
    space: dict = {}
    exec(compile("\n".join(lines), "<teachraster: a watched answer>", "exec"), space)
    code = space["_outer"]().__code__
    return code.replace(co_name=f.__code__.co_name, co_qualname=f.__code__.co_qualname)


def _swap(f) -> None:
    """Make every call of ``f`` note itself, then run ``f``'s own code (under ``_LOCK``)."""
    if f in _SWAPPED:
        _SWAPPED[f][2] += 1
        return
    original = types.FunctionType(f.__code__, f.__globals__, f.__name__, f.__defaults__,
                                  f.__closure__)  # fmt: skip
    original.__kwdefaults__ = f.__kwdefaults__

    def watch(args, kwargs):
        _noted(f, original, args, kwargs)
        return original(*args, **kwargs)

    _SWAPPED[f] = [f.__code__, f.__kwdefaults__, 1]
    f.__code__ = _stub_code(f)
    f.__kwdefaults__ = {"_watch_": watch}


def _unswap(f) -> None:
    entry = _SWAPPED[f]
    entry[2] -= 1
    if entry[2] == 0:
        f.__code__, f.__kwdefaults__ = entry[0], entry[1]
        del _SWAPPED[f]


@contextmanager
def watching(spec: Exercise):
    """While open, note every call of ``spec``'s listed answers, from any thread; yields the
    list of the :class:`~.exercise.PackageAnswer` seen called."""
    global _OPEN
    listed: dict = {}
    for answer in spec.answers:
        f = _function(answer)
        if f is not None:
            listed.setdefault(f, []).append(answer)
    seen: list = []
    window = (listed, seen)
    with _LOCK:
        for f in listed:
            _swap(f)
        _OPEN = (*_OPEN, window)
    try:
        yield seen
    finally:  # the checker's own code: no student frame is below it
        with _LOCK:
            _OPEN = tuple(w for w in _OPEN if w is not window)
            for f in listed:
                _unswap(f)


def names_read(fn, depth: int = 4) -> set[str]:
    """The names ``fn``'s code reads (attributes, globals) and the texts it (or its closure)
    holds, with those of its nested functions and of the functions it may call, its globals'
    and its closure's (``depth`` levels; the package's functions are not read)."""
    names: set[str] = set()
    done: set = set()
    todo = [(inspect.unwrap(fn) if callable(fn) else fn, 0)]
    while todo:
        f, level = todo.pop()
        code = getattr(f, "__code__", None)
        if code is None or code in done:
            continue
        done.add(code)
        codes = [code]
        while codes:
            c = codes.pop()
            names.update(c.co_names)
            names.update(k for k in c.co_consts if isinstance(k, str))
            codes += [k for k in c.co_consts if isinstance(k, types.CodeType)]
        names.update(v for v in _closed_over(f) if isinstance(v, str))
        if level < depth:
            todo += [(g, level + 1) for g in _helpers(f, names)]
    return names


def _closed_over(f) -> list:
    """What ``f``'s closure holds (its cells not filled yet left out)."""
    held = []
    for cell in getattr(f, "__closure__", None) or ():
        try:
            held.append(cell.cell_contents)
        except ValueError:
            pass
    return held


def _helpers(f, names) -> list:
    """The functions ``f`` may call that are not the package's: its globals named in
    ``names``, and its closure's."""
    found = [getattr(f, "__globals__", {}).get(name) for name in names] + _closed_over(f)
    return [g for g in found if isinstance(g, types.FunctionType)
            and not str(g.__module__).startswith("teachraster")]  # fmt: skip


def package_note(spec: Exercise, fn, seen) -> str | None:
    """Why ``fn`` does not count (it is the package's answer, its cases called one of them:
    ``seen``, from :func:`watching`, or its code reads the checker's private data), or None."""
    target = inspect.unwrap(fn) if callable(fn) else fn
    for answer in spec.answers:
        if target is inspect.unwrap(answer.function) and answer.when is None:
            return _words(spec, answer, "is")
    if seen:
        return _words(spec, seen[0], "calls")
    if spec.private:
        read = names_read(fn)
        for name, words in spec.private:
            if name in read:
                return f"your {spec.name} reads the checker's {name}: {words}"
    return None
