"""Read a student's answer as what the exercise asks for, or say exactly why it is not.

Every converter refuses ``None`` first, as a forgotten ``return`` ("your function returned
None (a missing `return`?)"), then text ("25.0" is not a number), then the wrong kind of
value, quoting the answer briefly. Numbers keep float32 (and float16) so that an explanation
can name a low-precision answer as the cause; every answer is capped in size before any work
is done on it, so that a huge return value cannot eat the check's time budget.
"""

from __future__ import annotations

import decimal
import numbers
import reprlib

import numpy as np

from .running import WrongAnswerType

#: The most vertices a clipped triangle may have (4, plus consecutive duplicates).
MAX_VERTICES = 64

_repr = reprlib.Repr()
_repr.maxstring = 40
_repr.maxother = 40
_repr.maxlist = _repr.maxtuple = 6


def short(value) -> str:
    """A short description of any value (a huge array or list is described, not printed;
    numpy scalars in a tuple or list as plain numbers, r12 09-8: "(np.float64(1.0), ...").

    >>> short((np.float64(1.0), np.int64(2))), short(np.zeros((12, 12), bool))
    ('(1.0, 2)', 'a bool array of shape (12, 12)')
    """
    if isinstance(value, np.ndarray):
        if value.size <= 6:
            return np.array2string(value, separator=", ", threshold=6).replace("\n", "")
        article = "an" if str(value.dtype)[0] in "aeio" else "a"
        return f"{article} {value.dtype} array of shape {value.shape}"
    return _repr.repr(_plain(value))


def _plain(value, depth: int = 2):
    """``value`` with the numpy scalars of a small tuple or list (``depth`` levels) made plain
    Python numbers, for its repr."""
    if isinstance(value, np.generic):
        return value.item()
    if type(value) in (tuple, list) and depth > 0 and len(value) <= 16:
        return type(value)(_plain(v, depth - 1) for v in value)
    return value


def _shaped(value, arr: np.ndarray) -> str:
    """``value`` described with its shape, once (an array's description already says it)."""
    text = short(value)
    return text if "of shape" in text else f"{text} of shape {arr.shape}"


def refuse_none_and_text(value, what: str) -> None:
    """Refuse None and text (:class:`~.running.WrongAnswerType`): the first refusals of every
    answer, also for answers of a kind of their own (a dict, a tuple of ints)."""
    if value is None:
        raise WrongAnswerType("returned None (a missing `return`?)")
    if isinstance(value, (str, bytes, np.str_, np.bytes_)):
        raise WrongAnswerType(
            f"returned the text {short(value)}, not {what}: return the value itself, not a "
            "string (no quotes, no str() or f-string)"
        )


def refuse_non_answers(value, what: str) -> None:
    """Refuse None, text, dicts and sets (:class:`~.running.WrongAnswerType`), for answers
    read by an exercise's own converter."""
    refuse_none_and_text(value, what)
    if isinstance(value, (dict, set, frozenset)):
        raise WrongAnswerType(f"returned a {type(value).__name__}, not {what}")


def _array(value, what: str, max_size: int) -> np.ndarray:
    """``value`` as an array of at most ``max_size`` elements, after the common refusals."""
    refuse_none_and_text(value, what)
    size = np.size(value) if isinstance(value, np.ndarray) else None
    if size is None and isinstance(value, (list, tuple)) and len(value) > max_size:
        size = len(value)
    if size is not None and size > max_size:
        raise WrongAnswerType(f"returned {short(value)}: {size} values where {what} is expected")
    try:
        return np.asarray(value)
    except (TypeError, ValueError) as exc:  # ragged lists and the like
        raise WrongAnswerType(f"returned {short(value)}, not {what} ({exc})") from None


def _to_float(arr: np.ndarray, value, what: str) -> np.ndarray:
    """Numbers as float64, or float32/float16 kept as such; text, bools, complex refused."""
    kind = arr.dtype.kind
    if kind == "f":  # a copy: the student may reuse (and change) the array it returned
        return arr.copy() if arr.dtype.itemsize < 8 else arr.astype(float)
    if kind in "iu":
        return arr.astype(float)
    if kind == "b":
        raise WrongAnswerType(f"returned {short(value)}, a bool, not {what}")
    if kind in "US":
        raise WrongAnswerType(f"returned the text {short(value)}, not {what}: return numbers")
    if kind == "c":
        raise WrongAnswerType(f"returned {short(value)}, complex, not {what}")
    if kind == "O":
        items = arr.ravel()
        for item in items:
            if item is None:
                raise WrongAnswerType(f"returned {short(value)}, which holds None, not {what}")
            if isinstance(item, (str, bytes)):
                raise WrongAnswerType(f"returned {short(value)}, which holds text, not {what}")
            real = isinstance(item, numbers.Real) or isinstance(item, decimal.Decimal)
            if isinstance(item, bool) or not real:
                of_type = f"of type {type(item).__name__}"
                where = f"({of_type})," if arr.ndim == 0 else f"holding a value {of_type},"
                raise WrongAnswerType(f"returned {short(value)} {where} not {what}")
        try:
            return np.array([float(x) for x in items], dtype=float).reshape(arr.shape)
        except OverflowError:
            raise WrongAnswerType(f"returned {short(value)}, too large for a float") from None
    raise WrongAnswerType(f"returned {short(value)}, not {what}")


def as_number(value):
    """One number (``np.float64``, or ``np.float32``/``np.float16`` kept as given).

    >>> float(as_number(3)), as_number(np.float32(0.5)).dtype
    (3.0, dtype('float32'))
    """
    what = "a number"
    if isinstance(value, (bool, np.bool_)):
        raise WrongAnswerType(f"returned {value}, a bool, not a number")
    arr = _array(value, what, 1)
    if arr.size != 1:
        raise WrongAnswerType(f"returned {short(value)}, {arr.size} values, not one number")
    return _to_float(arr, value, what).reshape(())[()]


def transposed_shape_words(shape: tuple, expected: tuple) -> str:
    """What to add to a shape error whose shape is the expected one reversed (r198 M1)."""
    if len(shape) == 2 and tuple(shape) == tuple(expected)[::-1] and shape[0] != shape[1]:
        return (
            " (the expected shape reversed: your answer is transposed, rows and columns "
            "swapped; an array is indexed [row, column], that is [y, x])"
        )
    return ""


def as_numbers(value, shape: tuple | None, what: str, max_size: int = MAX_VERTICES * 4):
    """An array of numbers of ``shape`` (-1 for any length; None: any shape, at most
    ``max_size`` values), float32 kept as given."""
    arr = _array(value, what, max_size)
    if shape is None:
        return _to_float(arr, value, what)
    fits = arr.ndim == len(shape) and all(s in (-1, n) for s, n in zip(shape, arr.shape))
    if not fits:
        flipped = transposed_shape_words(arr.shape, shape) if -1 not in shape else ""
        raise WrongAnswerType(f"returned {_shaped(value, arr)}; expected {what}{flipped}")
    return _to_float(arr, value, what)


def as_bool(value) -> bool:
    """True or False; 1 and 0 (int or float) count as such, other numbers are explained."""
    arr = _array(value, "a bool (True or False)", 1)
    if arr.size != 1:
        raise WrongAnswerType(f"returned {short(value)}, {arr.size} values, not one bool")
    if arr.ndim:  # r137 D8-7: np.array([True]) is an array of one bool, not a bool
        raise WrongAnswerType(
            f"returned {short(value)}, an array of shape {arr.shape}, not a bool: return its "
            "one value (bool(x[0])), or True or False itself"
        )
    kind = arr.dtype.kind
    if kind == "b":
        return bool(arr.item())
    if kind in "iuf" and arr.item() in (0, 1):
        return bool(arr.item())
    if kind in "iuf":
        raise WrongAnswerType(
            f"returned the number {short(arr.item())}, not a bool: return True or False (a "
            "comparison such as a < b gives one)"
        )
    _to_float(arr, value, "a bool (True or False)")  # explains text, complex, objects
    raise WrongAnswerType(f"returned {short(value)}, not a bool (True or False)")


def low_precision(value) -> str | None:
    """ "float32" (or "float16") when the answer was given in that type, else None."""
    dtype = getattr(value, "dtype", None)
    if dtype is not None and dtype.kind == "f" and dtype.itemsize < 8:
        return str(dtype)
    return None


def as_coverage(value, height: int, width: int) -> np.ndarray:
    """A (height, width) bool image; 0/1 ints or floats count as False/True.

    A (width, height) image is returned as it is, for the comparison to recognise a
    transposed answer; any other shape, and values other than 0/1/True/False, are explained.
    """
    what = f"a bool array of shape (height, width) = ({height}, {width})"
    arr = _array(value, what, 4 * height * width + 16)
    if arr.shape not in ((height, width), (width, height)):
        raise WrongAnswerType(f"returned {_shaped(value, arr)}; expected {what}")
    kind = arr.dtype.kind
    if kind == "b":
        return arr.astype(bool)
    if kind in "iuf":
        bad = ~np.isin(arr, (0, 1))
        if bad.any():
            i, j = np.argwhere(bad)[0]
            raise WrongAnswerType(
                f"returned an image holding {short(arr[i, j].item())} at row {i}, column {j}: "
                "coverage is True (or 1) where the pixel's centre is covered and False (or 0) "
                "elsewhere, no other values"
            )
        return arr.astype(bool)
    if kind == "O" and all(isinstance(x, (bool, np.bool_)) for x in arr.ravel()):
        return arr.astype(bool)  # r453 WF1: np.full((h, w), None) filled with covers' bools
    _to_float(arr, value, what)  # explains text, complex and objects
    raise WrongAnswerType(f"returned {short(value)}; expected {what}")
