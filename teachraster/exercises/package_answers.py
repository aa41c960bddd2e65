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

Two roads round the list (r12 09-1, 11-4). A private helper of the answer's own module
(``teachraster.core.lines._thin``, which ``tr.rasterize_line??`` shows; the checker's judge
``_same`` in exercise 11) is watched too, and counts as the package's answer when called from
outside the package (the package's own calls of it, from a public tool, do not count; the
module's public functions are tools, free to use). An answer may name further modules whose
every function is part of its computation (:attr:`~.exercise.PackageAnswer.modules`; r13
09-1: ``line_rules.diamond``, which ``_thin??`` shows), watched the same way. And a copy of the package's code (a
``types.FunctionType`` made of its ``__code__`` before the check, or its source pasted into a
cell) is not a call of it: :func:`copied` looks at the code of the student's function, of the
functions nested in it and of its own helpers, for the very code object of a listed answer or
private helper (a clone), or its instructions with the names and constants they read (a paste,
:func:`_print`; of a function of at least :data:`SMALLEST` instructions: a two-line helper may
be written alike by chance).
"""

from __future__ import annotations

import dataclasses
import dis
import importlib
import inspect
import sys
import threading
import types
from collections.abc import Iterable
from contextlib import contextmanager
from dataclasses import replace
from functools import cache, lru_cache

from .exercise import Exercise, PackageAnswer
from .interrupt import is_transparent

#: The fewest instructions a package function has for a pasted copy of its source to be named
#: (a two-line helper, ``np.r_[c[:3] * c[3], c[3]]``, is written alike by chance).
SMALLEST = 40

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
    if answer.label is not None:
        return f"teachraster's {answer.label}"
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


def _noted(f, original, args, kwargs, outside: bool) -> None:
    """Note a call of ``f`` in every open window that lists it (and whose ``when`` fits); a
    private helper's (``direct``) only when called from outside the package (``outside``)."""
    for listed, seen in _OPEN:
        for answer, direct in listed.get(f, ()):
            if direct and not outside:
                continue
            if answer not in seen and _matches(answer, original, args, kwargs):
                seen.append(answer)


def _module_helpers(spec: Exercise) -> list:
    """:func:`_scan_helpers`, read again only when a module it read has changed (a function
    bound anew: a test's monkeypatch) or ``spec`` lists other answers: a check asks three
    times, and the scan of every table of the checker's modules was a tenth of a check."""
    modules = dict.fromkeys(checker_modules(spec))
    for answer in spec.answers:
        f = _function(answer)
        if f is not None:
            modules.update(dict.fromkeys((f.__module__, *answer.modules)))
    stamp = (tuple(map(id, spec.answers)), tuple(spec.reference), spec.cases,
             tuple((m, tuple((k, id(v)) for k, v in vars(importlib.import_module(m)).items()))
                   for m in modules))  # fmt: skip
    with _LOCK:
        held = _HELPERS.get(id(spec))
    if held is None or held[0] is not spec or held[1] != stamp:
        held = (spec, stamp, _scan_helpers(spec))
        with _LOCK:
            _HELPERS[id(spec)] = held
    return list(held[2])


#: id(spec) -> (spec, what its scan read, the scan)
_HELPERS: dict = {}


def _scan_helpers(spec: Exercise) -> list:
    """The private functions of the modules of ``spec``'s listed answers (r12 09-1: ``_thin``
    passed 9.1 uncounted), and every function of the modules an answer names in
    :attr:`~.exercise.PackageAnswer.modules` (r13 09-1: ``line_rules.diamond``, reached from
    ``_thin??``), each as a :class:`PackageAnswer` with the words of the answer of its
    module; not the listed ones, nor a checker function whose ``finally`` the interrupt must
    pass through (:func:`~.interrupt.transparent`: its code must stay its own)."""
    listed = {_function(a) for a in spec.answers}
    out, done = [], set()
    for answer in spec.answers:
        f = _function(answer)
        if f is None:
            continue
        name = _name(answer).removeprefix("teachraster's ")
        # its own module listed in ``modules`` too: every function of it (r148 D12-5: the own
        # module was read first, privates only, and then skipped as read)
        own = (f.__module__, f.__module__ in answer.modules)
        for module, every in (own, *((m, True) for m in answer.modules)):
            if module in done:
                continue
            done.add(module)
            for key, value in vars(importlib.import_module(module)).items():
                g = inspect.unwrap(value) if callable(value) else value
                if (isinstance(g, types.FunctionType) and g.__module__ == module
                        and (every or key.startswith("_")) and not key.startswith("__")
                        and g not in listed and not is_transparent(_own_code(g))):  # fmt: skip
                    owner = _owner(spec, module, key) or name
                    # named by its own name (the answer's label names the answer alone)
                    out.append(replace(answer, function=g, when=None, modules=(), label=None,
                                       what=f"a part of {owner}'s own computation"))  # fmt: skip
    return out + _checker_helpers(spec, listed | {_function(a) for a in out})


def _owner(spec: Exercise, module: str, key: str) -> str | None:
    """The listed answer of ``module`` whose computation calls the helper ``key`` (directly or
    through the module's other functions), or None (r18 D-5: ``_porter_duff`` was called a
    part of ``from_straight``, which never calls it, not of ``straight_over``)."""
    names = vars(importlib.import_module(module))

    def reaches(f, seen) -> bool:
        code = getattr(f, "__code__", None)
        if code is None or f in seen:
            return False
        seen.add(f)
        return key in code.co_names or any(
            reaches(inspect.unwrap(names[n]), seen)
            for n in code.co_names
            if callable(names.get(n)) and getattr(names[n], "__module__", None) == module
        )

    for answer in spec.answers:
        f = _function(answer)
        if f is not None and f.__module__ == module and reaches(f, set()):
            return _name(answer).removeprefix("teachraster's ")
    return None


#: What the report says of a call into the checker's own module (r14 09-1).
CHECKER_WORDS = (
    "the checker's own code, which computes the expected answers: not counted (write the "
    "rule yourself; the checker is there to test it, not to hand in)"
)


def checker_modules(spec: Exercise) -> list[str]:
    """The modules of the checker that compute ``spec``'s expected answers: the one that
    builds its cases, and those :attr:`~.exercise.Exercise.reference` names."""
    return [spec.cases.__module__, *spec.reference]


def _checker_helpers(spec: Exercise, skip: set) -> list:
    """Every function of :func:`checker_modules` (r14 09-1: ``lines.diamond_pixels``, the
    checker's own rule with knobs, handed in as ``line_pixels`` passed unflagged), and every
    function of theirs held in their tables (:func:`_held`: ``blending.OVER[1][2]``, the
    lambda of a mistake of exercise ``over`` that is ``over_premultiplied``'s answer, passed
    unflagged), but the student's tools (what :mod:`teachraster.exercises` exports:
    ``broken_frame``), the ones in ``skip`` and the interrupt's transparent ones, each as a
    :class:`PackageAnswer` that says :data:`CHECKER_WORDS`."""
    from . import __all__ as names
    from . import __name__ as package

    tools = {inspect.unwrap(v) for v in (getattr(sys.modules[package], n, None) for n in names)
             if callable(v)}  # fmt: skip
    out, modules = [], tuple(dict.fromkeys(checker_modules(spec)))
    # each function first where its own module holds it (the path a student would type);
    # then one that only another checker module holds (a mistake's lambda made by a function
    # of one module and kept in an exercise of another: the blend checks' split)
    for own in (True, False):
        for module in modules:
            for key, value in vars(importlib.import_module(module)).items():
                if key.startswith("__") or key in names:
                    continue
                g = inspect.unwrap(value) if callable(value) else value
                found = [(g, None)] if isinstance(g, types.FunctionType) else _held(value, key)
                for h, label in found:
                    if ((h.__module__ == module if own else h.__module__ in modules)
                            and h not in tools and h not in skip
                            and not is_transparent(_own_code(h))):  # fmt: skip
                        skip = skip | {h}
                        named = None if label is None else f"{module.rsplit('.', 1)[-1]}.{label}"
                        out.append(PackageAnswer(h, words=CHECKER_WORDS, label=named))
    return out


def _held(value, path: str, depth: int = 4) -> list:
    """The functions a checker's table holds (a list, tuple or dict of them, or of
    :class:`~.exercise.Mistake` s and other dataclasses holding them; ``depth`` levels), each
    with the path a student would type to reach it (``OVER[1][2]``)."""
    if isinstance(value, types.FunctionType):
        return [(value, path)]
    if depth == 0 or isinstance(value, str | bytes | type):
        return []
    if isinstance(value, dict):
        items = [(f"{path}[{k!r}]", v) for k, v in value.items()]
    elif isinstance(value, list | tuple):
        items = [(f"{path}[{k}]", v) for k, v in enumerate(value)]
    elif dataclasses.is_dataclass(value):
        items = [(f"{path}.{f.name}", getattr(value, f.name)) for f in dataclasses.fields(value)]
    else:
        return []
    return [found for p, v in items for found in _held(v, p, depth - 1)]


def _own_code(f):
    """``f``'s own code, also while a window has it swapped for the stub."""
    return _SWAPPED[f][0] if f in _SWAPPED else f.__code__


def _stub_code(f):
    """A code object ``(*args, _watch_, **kwargs)`` that calls ``_watch_(args, kwargs)``, with
    as many free variables as ``f`` has (a function's code can only be swapped for one with
    as many), named as ``f``'s code for the tracebacks."""
    code = _stub_template(len(f.__code__.co_freevars))
    return code.replace(co_name=f.__code__.co_name, co_qualname=f.__code__.co_qualname)


@cache
def _stub_template(n_free: int):
    """The stub's code for ``n_free`` free variables, compiled once per count (a check swaps
    hundreds of functions: compiling each anew was a twentieth of a check's CPU)."""
    free = [f"_free{k}" for k in range(n_free)]
    lines = ["def _outer():", *(f"    {n} = None" for n in free),
             "    def stub(*args, _watch_=None, **kwargs):",
             *([f"        {', '.join(free)}"] if free else []),
             "        return _watch_(args, kwargs)",
             "    return stub"]  # fmt: skip
    space: dict = {}
    exec(compile("\n".join(lines), "<teachraster: a watched answer>", "exec"), space)
    return space["_outer"]().__code__


def _swap(f) -> None:
    """Make every call of ``f`` note itself, then run ``f``'s own code (under ``_LOCK``)."""
    if f in _SWAPPED:
        _SWAPPED[f][2] += 1
        return
    original = types.FunctionType(f.__code__, f.__globals__, f.__name__, f.__defaults__,
                                  f.__closure__)  # fmt: skip
    original.__kwdefaults__ = f.__kwdefaults__

    def watch(args, kwargs):
        caller = sys._getframe(2).f_globals.get("__name__", "")  # 0 watch, 1 the stub
        _noted(f, original, args, kwargs, not str(caller).startswith("teachraster"))
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
    for answer, direct in [*((a, False) for a in spec.answers),
                           *((a, True) for a in _module_helpers(spec))]:  # fmt: skip
        f = _function(answer)
        if f is not None:
            listed.setdefault(f, []).append((answer, direct))
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


def _walk(fn, depth: int = 4):
    """Each function ``fn`` may run, once: ``fn``, then the functions it may call that are not
    the package's (:func:`_helpers`, ``depth`` levels), as ``(function, its code objects with
    the nested ones, the names they read)``; a text among its constants or in its closure
    counts as a name (``getattr(bf, "_SALT")``). The one walk of both :func:`values_read` and
    :func:`_codes`, so that what is read and what is compared are the same functions."""
    done: set = set()
    todo = [(inspect.unwrap(fn) if callable(fn) else fn, 0)]
    while todo:
        f, level = todo.pop()
        code = getattr(f, "__code__", None)
        if code is None or code in done:
            continue
        done.add(code)
        codes, names, stack = [], set(), [code]
        while stack:
            c = stack.pop()
            codes.append(c)
            names.update(c.co_names)
            names.update(k for k in c.co_consts if isinstance(k, str))
            stack += [k for k in c.co_consts if isinstance(k, types.CodeType)]
        names.update(v for v in _closed_over(f) if isinstance(v, str))
        yield f, codes, names
        if level < depth:
            todo += [(g, level + 1) for g in _helpers(f, names)]


def values_read(fn, depth: int = 4) -> list:
    """The objects ``fn``'s code may read: its constants and its closure's, its globals named
    in its code, and the attributes so named (by a name or a text it holds) of the modules
    among them (``bf._KEY``, ``getattr(bf, "_SALT")``), with those of its nested functions and
    of the functions it may call, its globals' and its closure's (``depth`` levels; the
    package's functions are not read)."""
    values: list = []
    for f, codes, names in _walk(fn, depth):
        held = _closed_over(f)
        held += [k for c in codes for k in c.co_consts if not isinstance(k, types.CodeType)]
        space = getattr(f, "__globals__", {})
        held += [space[name] for name in names if name in space]
        modules = [v for v in held if isinstance(v, types.ModuleType)]
        held += [vars(m)[name] for m in modules for name in names if name in vars(m)]
        values += held
    return values


def _texts(value) -> set:
    """The texts a private value is or holds (a mapping's values, a sequence's items)."""
    if isinstance(value, str):
        return {value}
    items = value.values() if isinstance(value, dict) else value
    return {v for v in items if isinstance(v, str)} if isinstance(items, Iterable) else set()


def _reads(values: list, private) -> bool:
    """Is ``private`` among ``values``: the very object, an equal copy (by type and value), or
    one of its texts (r13 11-4: judged by the name, an honest constant named ``_KEY`` was
    refused and the key copied under another name passed)."""
    texts = _texts(private)
    for v in values:
        if v is private or (type(v) is type(private) and v == private):
            return True
        if isinstance(v, str) and v in texts:
            return True
        if isinstance(v, (dict, list, tuple, set, frozenset)) and texts & _texts(v):
            return True
    return False


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
    ``names``, and its closure's (a copy of a package function, made of its code, is not the
    package's: r12 09-1)."""
    found = [getattr(f, "__globals__", {}).get(name) for name in names] + _closed_over(f)
    return [g for g in found if isinstance(g, types.FunctionType) and not _genuine(g)]


def _genuine(g) -> bool:
    """Is ``g`` a function of the package, by name in its module (not a copy of one)?"""
    module = str(g.__module__)
    if not module.startswith("teachraster"):
        return False
    found = getattr(sys.modules.get(module), g.__name__, None)
    return found is g or inspect.unwrap(found) is g if callable(found) else False


def _codes(fn, depth: int = 4) -> list:
    """The code objects of ``fn``, of the functions nested in it, and of its own helpers
    (:func:`_walk`)."""
    return [c for _, codes, _ in _walk(fn, depth) for c in codes]


def names_read(fn, depth: int = 4) -> frozenset:
    """The global and attribute names that the code of ``fn``, of the functions nested in it
    and of its own helpers reads (``det`` of ``np.linalg.det``): what
    :attr:`~.exercise.Mistake.reads` asks of it."""
    return frozenset(name for code in _codes(fn, depth) for name in code.co_names)


#: The instructions by which a function's code reads a local of its own (Python 3.11–3.13): a
#: parameter read inside a nested function is a cell, made and closed over by the outer code.
_LOCAL_READS = frozenset({"LOAD_FAST", "LOAD_FAST_CHECK", "LOAD_FAST_LOAD_FAST", "LOAD_DEREF",
                          "LOAD_CLOSURE", "MAKE_CELL"})  # fmt: skip


def parameters_read(fn) -> frozenset:
    """The parameters of ``fn`` that its own code reads (r341 X-1: a trilinear that never
    reads its ``wrap`` did not pass it on; one that reads it calls a bilinear that ignores
    it): what :attr:`~.exercise.Mistake.unread` asks of it.

    >>> sorted(parameters_read(lambda texture, uv, wrap="repeat": texture[0] + uv))
    ['texture', 'uv']
    """
    code = getattr(fn, "__code__", None)
    if code is None:
        return frozenset()
    flags = code.co_flags
    n = code.co_argcount + code.co_kwonlyargcount
    n += bool(flags & inspect.CO_VARARGS) + bool(flags & inspect.CO_VARKEYWORDS)
    loaded = set()
    for i in dis.get_instructions(code):
        if i.opname in _LOCAL_READS:
            loaded.update(i.argval if isinstance(i.argval, tuple) else (i.argval,))
    return frozenset(loaded.intersection(code.co_varnames[:n]))


@lru_cache(maxsize=4096)  # the package's codes are read again at every check
def _print(code) -> tuple:
    """What a copy of ``code`` keeps: its instructions with the names and constants they read
    (nested code by its own print; locals by their place, so that renaming them changes
    nothing), never its file, lines, name or docstring. Jumps by kind, not target, and a
    method load as an attribute load: the same source compiles to either, depending on
    whether ``np`` was imported in the same cell (Python 3.11)."""
    out = []
    for i in dis.get_instructions(code):
        op = "LOAD_ATTR" if i.opname == "LOAD_METHOD" else i.opname
        if i.opcode in dis.hasjrel or i.opcode in dis.hasjabs:
            arg = None
        elif i.opcode in dis.haslocal or i.opcode in dis.hasfree:
            arg = i.arg
        elif isinstance(i.argval, types.CodeType):
            arg = _print(i.argval)
        else:
            arg = repr(i.argval)
        out.append((op, arg))
    return tuple(out)


def copied(spec: Exercise, fn) -> PackageAnswer | None:
    """The listed answer or private helper (:func:`_module_helpers`) whose code ``fn`` (or a
    function nested in it, or a helper of its own) holds, copied: the very code object (a
    clone made of ``__code__``, any size), or the same instructions (:func:`_print`: source
    pasted, at least :data:`SMALLEST` instructions); None if none."""
    own, pasted = {}, {}
    for answer in [*spec.answers, *_module_helpers(spec)]:
        f = _function(answer)
        if f is not None:
            code = _own_code(f)
            own.setdefault(code, answer)
            mine = _print(code)
            if len(mine) >= SMALLEST:
                pasted.setdefault(mine, answer)
    for code in _codes(fn):
        found = own.get(code) if any(code is c for c in own) else pasted.get(_print(code))
        if found is not None:
            return found
    return None


def package_note(spec: Exercise, fn, seen) -> str | None:
    """Why ``fn`` does not count (it is the package's answer, its cases called one of them:
    ``seen``, from :func:`watching`, or its code reads the checker's private data), or None."""
    target = inspect.unwrap(fn) if callable(fn) else fn
    for answer in spec.answers:
        if target is inspect.unwrap(answer.function) and answer.when is None:
            return _words(spec, answer, "is")
    for answer in _module_helpers(spec):  # handed in itself, not a copy of it
        if target is answer.function:
            return _words(spec, answer, "is")
    copy = copied(spec, fn)  # first: a pasted copy calls the module's helpers as well
    if copy is not None:
        return _words(spec, copy, "runs a copy of the code of")
    if seen:
        return _words(spec, seen[0], "calls")
    if spec.private:
        read = values_read(fn)
        for name, value, words in spec.private:
            if _reads(read, value):
                return f"your {spec.name} reads the checker's {name}: {words}"
    return None
