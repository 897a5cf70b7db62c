"""Tests of the Python package (python/recstab), run by tests/cli/suite_api.sh.

Expected values, derived independently of recstab:
  - central difference on x'' = -w^2 x: p = l^2 - (2 - w^2) l + 1, roots on
    the unit circle for 0 < w < 2, a root of modulus > 1 for w > 2 (Hughes,
    The Finite Element Method, ch. 9); at w = 3, p = l^2 + 7 l + 1;
  - x[n+1] = a x[n]: the root a, stable iff |a| < 1, so on the map of
    a in [-2, 2] (5 points) x b in [0, 1] (2 points, b unused) the columns
    a = -2, 2 are unstable, a = -1, 1 marginal, a = 0 stable.
The document must also be exactly the command's (`recstab --json`)."""
import json
import os
import subprocess

import pytest

import recstab

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CD = os.path.join(ROOT, "cases", "textbook", "central-difference.case")
BIN = os.path.join(ROOT, os.environ.get("BUILD", "build"), "recstab")


def _strip(j):
    if isinstance(j, dict):
        return {k: _strip(v) for k, v in j.items() if k not in ("seconds", "seconds_points", "threads")}
    if isinstance(j, list):
        return [_strip(v) for v in j]
    return j


def test_analyse_path_is_the_command_document():
    doc = recstab.analyse(CD)
    out = subprocess.run([BIN, "--json", CD], capture_output=True, check=True).stdout
    assert _strip(doc) == _strip(json.loads(out))


def test_analyse_text_set_and_analyses():
    with open(CD, encoding="utf-8") as f:
        text = f.read()
    doc = recstab.analyse(text, set={"w": 3}, analyses=["charpoly", "stability"])
    res = doc["cases"][0]["results"]
    assert [r["analysis"] for r in res] == ["charpoly", "stability"]
    assert "lambda^2 + 7*lambda + 1" in json.dumps(res[0])
    assert "unstable" in json.dumps(res[1])


def test_failed_claim_is_a_document_with_status_1():
    status, doc = recstab.analyse_status(CD, analyses=["claim bounded when w < 3"])
    assert status == 1
    assert doc["cases"][0]["results"][0]["analysis"] == "claim"


def test_bad_input_raises_with_place():
    with pytest.raises(recstab.InputError) as e:
        recstab.analyse("param w\nunknown x\neq x[n+1] = x[n] +\n", source_name="bad.case")
    assert e.value.status == 2 and e.value.file == "bad.case" and e.value.line == 3
    with pytest.raises(recstab.InputError):
        recstab.analyse(CD, set={"nosuch": 1})


def test_point_budget_raises_limit_error():
    # a 3000 x 3000 map has 9e6 points, over the default limit of 4e6 points
    # per map (README, --max-points): refused before any work, code "limit"
    case = "param a\nparam b\nunknown x\neq x[n+1] = a*x[n]\n"
    with pytest.raises(recstab.LimitError) as e:
        recstab.analyse(case, analyses=["map a -2 2 3000, b 0 1 3000"])
    assert e.value.status == 2 and "9000000 points" in str(e.value)


def test_time_budget_raises_limit_error():
    # the engine counts at least 1 us per point (a fixed lower bound in
    # rs_sweep_estimate): 2e6 points need 2 s, refused under a 1 s limit
    # before any work (as `recstab --time-limit 1` does)
    case = "param a\nparam b\nunknown x\neq x[n+1] = a*x[n]\n"
    with pytest.raises(recstab.LimitError) as e:
        recstab.analyse(case, analyses=["map a -2 2 2000, b 0 1 1000"], time_limit=1)
    assert "time limit of 1 s" in str(e.value)


def test_map_array():
    np = pytest.importorskip("numpy")
    case = "param a\nparam b\nunknown x\neq x[n+1] = a*x[n]\n"
    m = recstab.map_array(case, analyses=["map a -2 2 5, b 0 1 2"])
    assert m["params"] == ["a", "b"]
    assert np.allclose(m["x"], [-2, -1, 0, 1, 2]) and np.allclose(m["y"], [0, 1])
    assert m["verdict"].shape == (2, 5)
    assert list(m["verdict"][0]) == ["unstable", "marginal", "stable", "marginal", "unstable"]
    assert np.allclose(m["radius"][1], [2, 1, 0, 1, 2], atol=1e-9)


def test_derivation_reprs():
    d = recstab.derivation(CD)
    md, tex = d._repr_markdown_(), d._repr_latex_()
    assert md.startswith("## Central difference")
    assert "\\section*{Central difference" in tex
    assert "lambda" in md


class _Axes:
    """records what plot draws (no matplotlib needed)"""
    def plot(self, xs, ys):
        self.xs, self.ys = xs, ys

    def set_xlabel(self, t):
        self.xlabel = t

    def set_ylabel(self, t):
        self.ylabel = t


def test_plot_sweep_values():
    # central difference, radius over w = 0, 1/2, ..., 4: 1 on (0, 2]
    # (roots on the circle; at w = 0 and 2 a double root of modulus 1); at
    # w = 5/2, p = l^2 + 17/4 l + 1 = (l + 4)(l + 1/4): radius 4; at w = 3,
    # (7 + sqrt 45)/2
    ax = recstab.plot(CD, analyses=["sweep w from 0 to 4 steps 8"], ax=_Axes(), labels={"w": "$\\omega h$"})
    assert ax.xs == [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4]
    assert ax.ys[:5] == [1, 1, 1, 1, 1]
    assert abs(ax.ys[5] - 4) < 1e-9 and abs(ax.ys[6] - (7 + 45 ** 0.5) / 2) < 1e-9
    assert ax.xlabel == "$\\omega h$" and ax.ylabel == "radius"


def test_plot_when_matplotlib_is_there():
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    case = "param a\nparam b\nunknown x\neq x[n+1] = a*x[n]\n"
    ax = recstab.plot(case, analyses=["map a -2 2 5, b 0 1 2"], labels={"a": "$a$"})
    assert ax.get_xlabel() == "$a$"
