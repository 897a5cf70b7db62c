"""Every CSV file recstab writes is one pandas-ready table (issue 16):
``pandas.read_csv(path, comment="#")`` gives one table, with the columns of
its header line and no row of another table merged in; recstab.table()
gives the same table from the JSON document.  Skipped (with the reason)
when pandas cannot be imported (Debian: python3-pandas, in `make deps`).

Expected values, derived independently of recstab:
  - x[n+1] = (a + b) x[n]: the one root a + b, so a point is stable iff
    |a + b| < 1, marginal iff |a + b| = 1 (a simple root on the circle),
    unstable iff |a + b| > 1, and the spectral radius is |a + b|;
  - its exact stability boundary is the two lines a + b = 1 and a + b = -1
    (p(1) = 1 - a - b, p(-1) = -(1 + a + b)); both are linear in a and in
    b, so a crossing placed between two grid points by linear interpolation
    lies exactly on a line (up to the doubles' rounding);
  - grid values: K points from A to B are A + k (B - A) / (K - 1)."""
import json
import os
import subprocess
from fractions import Fraction

import pytest

pd = pytest.importorskip("pandas", reason="pandas cannot be imported (Debian: apt-get install python3-pandas)")

import recstab

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
BIN = os.path.join(ROOT, os.environ.get("BUILD", "build"), "recstab")
CASE = "param a\nparam b\nunknown x\neq x[n+1] = (a+b)*x[n]\n"
MAP = "map a -2 2 4, b -1 1 3"
SWEEP = "sweep a from -2 to 2 steps 8 at b=1/2"
# the columns of a map's table (README, "Tables"), NAME1 = a, NAME2 = b
MAP_COLUMNS = ["index", "i", "j", "a", "b", "a_exact", "b_exact", "verdict", "code", "radius",
               "radius_lower", "radius_upper", "decided_by"]


def _verdict(s):
    return "stable" if abs(s) < 1 else "marginal" if abs(s) == 1 else "unstable"


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """One run with a map (and its boundary) and a sweep: the CSV files and
    the JSON document of the same run."""
    d = tmp_path_factory.mktemp("tables")
    case = d / "ab.case"
    case.write_text(CASE)
    csv = d / "t.csv"
    out = subprocess.run([BIN, "--json", "--csv", str(csv), "--analyse", MAP, "--analyse", SWEEP, str(case)],
                         capture_output=True, check=True).stdout
    return d, json.loads(out)


def _read(path):
    return pd.read_csv(path, comment="#")


def test_every_file_is_one_table(run):
    d, doc = run
    files = sorted(p.name for p in d.glob("*.csv"))
    assert files == ["t.2.csv", "t.boundary.csv", "t.csv"]
    for name in files:
        text = (d / name).read_text().splitlines()
        # comments only before the one header line
        body = [l for l in text if not l.startswith("#")]
        assert all(l.startswith("#") for l in text[:len(text) - len(body)])
        df = _read(d / name)
        assert list(df.columns) == body[0].split(",")
        assert len(df) == len(body) - 1
        assert not df.columns.str.startswith("Unnamed").any()


def test_map_table(run):
    d, doc = run
    df = _read(d / "t.csv")
    assert list(df.columns) == MAP_COLUMNS
    assert len(df) == 4 * 3
    xs = [Fraction(-2) + k * Fraction(4, 3) for k in range(4)]
    ys = [Fraction(-1), Fraction(0), Fraction(1)]
    for _, r in df.iterrows():
        a, b = xs[r["i"]], ys[r["j"]]
        assert r["index"] == r["j"] * 4 + r["i"]
        assert r["a"] == pytest.approx(float(a)) and r["b"] == pytest.approx(float(b))
        # the exact columns are the fractions, as text
        assert Fraction(str(r["a_exact"])) == a and Fraction(str(r["b_exact"])) == b
        assert r["verdict"] == _verdict(a + b)
        # certified bounds (doubles rounded outward) around the exact radius
        assert Fraction(r["radius_lower"]) <= abs(a + b) <= Fraction(r["radius_upper"])
    m = recstab._results(doc, "map")[0]
    assert list(m["columns"]) == MAP_COLUMNS


def test_boundary_table(run):
    d, doc = run
    df = _read(d / "t.boundary.csv")
    assert list(df.columns) == ["condition", "a", "b", "scan"]
    assert len(df) > 0
    assert set(df["scan"]) <= {"zero", "row", "column"}
    for _, r in df.iterrows():
        assert abs(abs(r["a"] + r["b"]) - 1) < 1e-9


def test_sweep_table(run):
    d, doc = run
    df = _read(d / "t.2.csv")
    s = recstab._results(doc, "sweep")[0]
    assert list(df.columns) == list(s["columns"])
    assert len(df) == 9
    for _, r in df.iterrows():
        a = -2 + r["index"] * 0.5
        assert r["a"] == pytest.approx(a)
        assert r["verdict"] == _verdict(a + 0.5)


def test_table_helper_is_the_csv(run):
    """recstab.table() of the JSON elements: the frames read from the files."""
    d, doc = run
    m = recstab._results(doc, "map")[0]
    s = recstab._results(doc, "sweep")[0]
    for frame, path in ((recstab.table(m), "t.csv"), (recstab.table(m, boundary=True), "t.boundary.csv"),
                        (recstab.table(s), "t.2.csv")):
        df = _read(d / path)
        assert list(frame.columns) == list(df.columns)
        assert len(frame) == len(df)
        for c in df.columns:
            if c.endswith("_exact"):
                assert [str(v) for v in frame[c]] == [str(v) for v in df[c]]
            elif df[c].dtype.kind in "fi":
                assert frame[c].astype(float).tolist() == pytest.approx(df[c].astype(float).tolist())
            else:
                assert frame[c].tolist() == df[c].tolist()


def test_map_array_is_the_csv(run):
    np = pytest.importorskip("numpy")
    d, doc = run
    arr = recstab.map_array(doc)
    df = _read(d / "t.csv")
    assert arr["verdict"].shape == (3, 4)
    for _, r in df.iterrows():
        assert arr["verdict"][r["j"], r["i"]] == r["verdict"]
        assert arr["radius_upper"][r["j"], r["i"]] == pytest.approx(r["radius_upper"])
    assert np.allclose(arr["x"], [-2 + k * 4 / 3 for k in range(4)])
