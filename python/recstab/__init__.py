"""recstab -- exact and certified stability of time-stepping schemes, from Python.

A thin ctypes layer over librecstab.so: every analysis runs in the library
exactly as the ``recstab --json`` command runs it, and comes back as the same
JSON document (a dict).

    >>> import recstab
    >>> doc = recstab.analyse("cases/textbook/central-difference.case", set={"w": "1"})
    >>> doc["cases"][0]["results"][0]["analysis"]
    'charpoly'

numpy (``map_array``) and matplotlib (``plot``) are optional.
"""
import ctypes
import ctypes.util
import json
import os

__all__ = ["analyse", "analyze", "analyse_status", "cases", "table", "map_array", "plot", "Derivation", "derivation",
           "RecstabError", "InputError", "LimitError", "InconsistentError", "library_path"]


class RecstabError(Exception):
    """A run that gave no document: bad input, a limit, or an internal error.

    ``status`` is the command's exit status (2 or 3), ``code`` the library's
    error code name ("input", "limit", "math", ...), ``file``, ``line``,
    ``col`` where in the case text the error is (when known)."""

    def __init__(self, status, error):
        super().__init__(error.get("message", "recstab error"))
        self.status = status
        self.code = error.get("code")
        self.file = error.get("file") or None
        self.line = error.get("line") or None
        self.col = error.get("col") or None


class InputError(RecstabError, ValueError):
    """Bad input: the case text, a ``set`` value or an analysis request (exit 2)."""


class LimitError(RecstabError):
    """A resource limit: time, memory, precision, degree (exit 2)."""


class InconsistentError(RecstabError):
    """Two of recstab's own methods disagreed, or an internal error (exit 3)."""


def _find_library():
    cand = []
    if os.environ.get("RECSTAB_LIBRARY"):
        cand.append(os.environ["RECSTAB_LIBRARY"])
    here = os.path.dirname(os.path.abspath(__file__))
    # the source tree: python/recstab/ next to build/
    cand.append(os.path.join(here, "..", "..", "build", "librecstab.so"))
    try:
        from . import _installed   # written by make install
        cand.append(_installed.LIBRARY)
    except ImportError:
        pass
    found = ctypes.util.find_library("recstab")
    if found:
        cand.append(found)
    for c in cand:
        if os.path.sep not in c or os.path.exists(c):
            return c
    raise ImportError("librecstab.so not found: build it (make) or set RECSTAB_LIBRARY")


library_path = _find_library()
_lib = ctypes.CDLL(library_path)
_lib.rs_analyse_json_with.restype = ctypes.c_int
_lib.rs_analyse_json_with.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p),
                                      ctypes.POINTER(ctypes.c_char_p), ctypes.c_int, ctypes.c_double,
                                      ctypes.c_long, ctypes.POINTER(ctypes.c_void_p)]
_lib.rs_free.restype = None
_lib.rs_free.argtypes = [ctypes.c_void_p]


def _strings(items):
    if not items:
        return None
    arr = (ctypes.c_char_p * (len(items) + 1))()
    for k, s in enumerate(items):
        arr[k] = s.encode("utf-8")
    arr[len(items)] = None
    return arr


def _read_case(text_or_path):
    """(text, source name): a path when it names a file, else the text itself."""
    if isinstance(text_or_path, os.PathLike) or (
            isinstance(text_or_path, str) and "\n" not in text_or_path and os.path.isfile(text_or_path)):
        path = os.fspath(text_or_path)
        with open(path, encoding="utf-8") as f:
            return f.read(), path
    return text_or_path, "<string>"


def analyse_status(text_or_path, set=None, analyses=None, source_name=None, scheme=False,
                   time_limit=None, memory_limit=None):
    """(exit status, document): like ``analyse`` but status 1 and 3 are returned, not raised."""
    text, source = _read_case(text_or_path)
    if source_name is not None:
        source = source_name
    sets = ["%s=%s" % (k, v) for k, v in (set or {}).items()]
    out = ctypes.c_void_p()
    status = _lib.rs_analyse_json_with(text.encode("utf-8"), source.encode("utf-8"), _strings(sets),
                                       _strings(list(analyses or [])), 1 if scheme else 0,
                                       -1.0 if time_limit is None else float(time_limit),
                                       -1 if memory_limit is None else int(memory_limit), ctypes.byref(out))
    if not out.value:
        raise MemoryError("librecstab returned no document")
    try:
        doc = json.loads(ctypes.string_at(out.value).decode("utf-8"))
    finally:
        _lib.rs_free(out)
    return status, doc


def analyse(text_or_path, set=None, analyses=None, source_name=None, scheme=False,
            time_limit=None, memory_limit=None):
    """Run a case (its text, or the path of a case file) and return its JSON document.

    ``set``: values like ``--set`` (``{"w": "1/2"}``), ``analyses``: requests
    replacing the case's own, like ``--analyse`` (``["region w"]``).  A failed
    claim or expectation (exit status 1) is part of the document (its
    result's "holds" is false); errors raise ``InputError``, ``LimitError``
    (the budget) or ``InconsistentError``.  ``scheme=True`` adds the
    "scheme" that derivations show (as --markdown and --latex do);
    ``time_limit`` (seconds) and ``memory_limit`` (MB) are the budget of
    --time-limit and --memory-limit (None: 600 s and half of the RAM; 0: none)."""
    status, doc = analyse_status(text_or_path, set, analyses, source_name, scheme, time_limit, memory_limit)
    if "error" in doc and len(doc) == 1:
        err = doc["error"]
        cls = InconsistentError if status == 3 else LimitError if err.get("code") == "limit" else InputError
        raise cls(status, err)
    if status == 3:
        raise InconsistentError(status, {"code": "inconsistent",
                                         "message": "two of recstab's methods disagree (see the document)"})
    return doc


analyze = analyse


def cases(doc):
    """The case documents of a document: ``doc["cases"]`` (the shape of every
    document), or ``[doc]`` for one case's document taken out of it."""
    return doc["cases"] if "cases" in doc else [doc]


def _results(doc, kind):
    return [r for d in cases(doc) for r in d.get("results", []) if r.get("analysis") == kind]


def table(element, boundary=False):
    """The rows of a sweep or map element as a pandas DataFrame (columns
    as in the CSV file; needs pandas); ``boundary=True``: its boundary rows."""
    import pandas as pd
    if boundary:
        return pd.DataFrame(element["boundary_rows"], columns=element["boundary"]["columns"])
    return pd.DataFrame(element["rows"], columns=element["columns"])


def map_array(doc_or_case, index=0, **kw):
    """The map of a document (or of ``analyse(doc_or_case, **kw)``) as numpy arrays.

    Returns a dict: ``x``, ``y`` the grid values of the two parameters
    (``params`` their names), and for each column of the map's table
    (``verdict``, ``code``, ``radius``, ...) an array of shape (len(y), len(x)),
    entry [j, i] at (x[i], y[j]); points not computed are nan (or "")."""
    import numpy as np
    doc = doc_or_case if isinstance(doc_or_case, dict) else analyse(doc_or_case, **kw)
    maps = _results(doc, "map")
    if len(maps) <= index:
        raise ValueError("the document has %d map(s), no map %d" % (len(maps), index))
    m = maps[index]
    if m.get("rows_omitted"):
        raise ValueError("the document holds %d of the map's rows (--json-rows)" % len(m["rows"]))
    cols = m["columns"]
    nx, ny = m["grid"]
    px, py = m["params"]
    out = {"params": [px, py]}
    data = {c: [row[k] for row in m["rows"]] for k, c in enumerate(cols)}
    ii = np.array(data["i"], dtype=int)
    jj = np.array(data["j"], dtype=int)
    x = np.full(nx, np.nan)
    y = np.full(ny, np.nan)
    x[ii] = np.array(data[px], dtype=float)
    y[jj] = np.array(data[py], dtype=float)
    out["x"], out["y"] = x, y
    for c in cols:
        if c in ("index", "i", "j"):
            continue
        try:
            vals = np.array([float(v) if v is not None else np.nan for v in data[c]])
            a = np.full((ny, nx), np.nan)
        except (ValueError, TypeError):
            vals = np.array(data[c], dtype=object)
            a = np.full((ny, nx), "", dtype=object)
        a[jj, ii] = vals
        out[c] = a
    return out


def plot(doc_or_case, index=0, ax=None, labels=None, **kw):
    """Plot a map (its stability codes over the grid: 0 stable, 1 marginal,
    2 unstable, 3 singular) or, without a map, a sweep (the quantity it
    sweeps, "radius" by default) with matplotlib; returns the Axes.
    ``labels``: axis labels by parameter or column name (LaTeX allowed).
    ``ax``: an Axes to draw into (default: a new figure)."""
    if ax is None:
        import matplotlib.pyplot as plt
        ax = plt.figure().gca()
    labels = labels or {}
    doc = doc_or_case if isinstance(doc_or_case, dict) else analyse(doc_or_case, **kw)
    if _results(doc, "map"):
        m = map_array(doc, index)
        px, py = m["params"]
        ax.pcolormesh(m["x"], m["y"], m["code"], shading="nearest", cmap="RdYlGn_r", vmin=0, vmax=3)
        ax.set_xlabel(labels.get(px, px))
        ax.set_ylabel(labels.get(py, py))
        return ax
    sweeps = _results(doc, "sweep")
    if len(sweeps) <= index:
        raise ValueError("the document has no map and %d sweep(s), no sweep %d" % (len(sweeps), index))
    s = sweeps[index]
    cols = s["columns"]
    rows = s["rows"]
    p = s["param"]
    ycol = s.get("of") if s.get("of") in cols else "radius"
    xs = [float(r[cols.index(p)]) for r in rows]
    ys = [float(r[cols.index(ycol)]) if r[cols.index(ycol)] is not None else float("nan") for r in rows]
    ax.plot(xs, ys)
    ax.set_xlabel(labels.get(p, p))
    ax.set_ylabel(labels.get(ycol, ycol))
    return ax


class Derivation:
    """A case's derivation for Jupyter: shown as Markdown (``_repr_markdown_``)
    or LaTeX (``_repr_latex_``), rendered by the library from the document."""

    def __init__(self, markdown, latex):
        self.markdown = markdown
        self.latex = latex

    def _repr_markdown_(self):
        return self.markdown

    def _repr_latex_(self):
        return self.latex


# The derivation is rendered by the library into a memory stream (libc's
# open_memstream): rs_derivation_markdown / rs_derivation_latex take a FILE *
# and jansson's json_t (jansson is a dependency of librecstab.so).
_libc = ctypes.CDLL(None)
_libc.open_memstream.restype = ctypes.c_void_p
_libc.open_memstream.argtypes = [ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_size_t)]
_libc.fclose.argtypes = [ctypes.c_void_p]
_libc.free.argtypes = [ctypes.c_void_p]
_lib.json_loads.restype = ctypes.c_void_p
_lib.json_loads.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_void_p]
_lib.json_delete.argtypes = [ctypes.c_void_p]
_lib.rs_derivation_markdown.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
_lib.rs_derivation_latex.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int]


def _render(doc, latex):
    j = _lib.json_loads(json.dumps(doc).encode("utf-8"), 0, None)
    if not j:
        raise ValueError("the document cannot be read back")
    buf, size = ctypes.c_void_p(), ctypes.c_size_t()
    f = _libc.open_memstream(ctypes.byref(buf), ctypes.byref(size))
    try:
        if latex:
            _lib.rs_derivation_latex(f, j, 0)
        else:
            _lib.rs_derivation_markdown(f, j)
    finally:
        _libc.fclose(f)
        _lib.json_delete(j)   # the reference count was 1: json_decref is inline
    try:
        return ctypes.string_at(buf.value, size.value).decode("utf-8")
    finally:
        _libc.free(buf)


def derivation(doc_or_case, **kw):
    """The derivation of a case (a document made with ``scheme=True``, case
    text or path) for Jupyter: Markdown and LaTeX as the command's
    --markdown and --latex print them (LaTeX without the preamble)."""
    doc = doc_or_case if isinstance(doc_or_case, dict) else analyse(doc_or_case, scheme=True, **kw)
    docs = cases(doc)
    return Derivation("".join(_render(d, False) for d in docs), "".join(_render(d, True) for d in docs))
