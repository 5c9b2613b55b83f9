"""escape() and diffuse(): NumPy out, the summaries as the library computes
them, the same document as the command line, typed refusals."""

import json
import os
import subprocess

import numpy as np
import pytest

import spinball as sb


def test_escape_records_and_summary():
    r = sb.escape("stadium:a=1,hole=0.3", 0.4, ics=200, collisions=3000, seed=5, threads=2)
    n = len(r.times)
    assert n == 200
    assert r.escaped + r.n_censored == 200
    assert r.censored.dtype == np.bool_ and r.censored.sum() == r.n_censored
    # A censored ball has no exit; an escaped one has it.
    assert np.isnan(r.exit_s[r.censored]).all()
    assert np.isfinite(r.exit_s[~r.censored]).all()
    assert r.exit_point.shape == (200, 2)
    p = r.survival()
    assert p is not None and (p["lower"] <= p["p"]).all() and (p["p"] <= p["upper"]).all()
    assert np.all(np.diff(p["p"]) <= 0)
    # The summary's numbers are the dict's.
    s = r.summary
    assert s["escaped"] == r.escaped
    t = s["time"]["fit"]
    mean = r.mean_escape()
    assert mean == (t["mean"]["mean"], t["mean"]["sem"], t["mean"]["complete"])
    rate = r.escape_rate()
    if rate is None:
        assert "refused" in t["rate"]
    else:
        assert rate == (t["rate"]["fit"]["gamma"], t["rate"]["fit"]["sem"])
    assert r.kac_ratio() is not None
    # One thread or two: the same document.
    one = sb.escape("stadium:a=1,hole=0.3", 0.4, ics=200, collisions=3000, seed=5, threads=1)
    assert one.to_json() == r.to_json()
    assert json.loads(r.to_json())["kind"] == "spinball.escape"


def test_tables_with_holes_and_lorentz_gases_from_python():
    t = sb.SegmentTable.stadium_with_hole(1.0, 2.0 + np.pi / 2, 0.3)
    assert t.kinds.count("hole") == 1
    a = sb.escape(t, 0.4, ics=50, collisions=500, seed=5)
    b = sb.escape("stadium:a=1,hole=0.3", 0.4, ics=50, collisions=500, seed=5)
    assert np.array_equal(a.times, b.times)
    gas = sb.LorentzGas("square", 1.0, 0.4)
    assert gas.horizon == "infinite" and gas.spec == "lorentz:lattice=square,w=1,R=0.4"
    assert sb.LorentzGas("triangular", 1.0, 0.45).horizon == "finite"
    cell = gas.table()
    assert cell.kinds.count("periodic") == 4
    d = sb.diffuse(cell, 0.0, ics=20, times=[5, 10, 15, 20], seed=1)
    assert d.horizon == "infinite"
    assert d.diffusion_coefficient is None and d.marginal_coefficient is not None
    with pytest.raises(ValueError, match="square or triangular"):
        sb.LorentzGas("hexagonal")


def test_diffusion_arrays():
    d = sb.diffuse("lorentz:lattice=triangular,w=1,R=0.45", 0.4, ics=40, until=40, checkpoints=8, seed=3)
    assert d.displacements.shape == (40, 8, 2)
    r2 = (d.displacements ** 2).sum(axis=2)
    assert np.allclose(d.msd, r2.mean(axis=0), rtol=1e-12)
    assert d.horizon == "finite"
    D, sem = d.diffusion_coefficient
    assert sem > 0 and d.window == (20.0, 40.0)
    assert d.marginal_coefficient is None


def test_refusals_say_what_to_do():
    with pytest.raises(ValueError, match="add one"):
        sb.escape("stadium:a=1", 0.4, ics=10)
    with pytest.raises(ValueError, match="no periodic walls"):
        sb.diffuse("stadium:a=1", 0.4, ics=10)
    with pytest.raises(ValueError, match="no periodic walls"):
        sb.diffuse("stadium:a=1,hole=0.2", 0.4, ics=10)


def spinball_cli():
    exe = os.environ.get("SPINBALL")
    if not exe:
        pytest.skip("SPINBALL (the spinball binary) is not set")
    return exe


def test_the_command_line_writes_the_same_documents(tmp_path):
    exe = spinball_cli()
    path = tmp_path / "e.json"
    subprocess.run(
        [exe, "escape", "--table", "stadium:a=1,hole=0.3", "--alpha", "0.4", "--ics", "100",
         "--collisions", "2000", "--seed", "5", "--json", str(path), "--quiet"],
        check=True,
    )
    r = sb.escape("stadium:a=1,hole=0.3", 0.4, ics=100, collisions=2000, seed=5)
    assert path.read_text() == r.to_json() + "\n"
    path = tmp_path / "d.json"
    subprocess.run(
        [exe, "diffuse", "--table", "lorentz:lattice=triangular,w=1,R=0.45", "--alpha", "0.4",
         "--ics", "30", "--until", "40", "--checkpoints", "8", "--seed", "3", "--json", str(path),
         "--quiet"],
        check=True,
    )
    d = sb.diffuse("lorentz:lattice=triangular,w=1,R=0.45", 0.4, ics=30, until=40, checkpoints=8, seed=3)
    assert path.read_text() == d.to_json() + "\n"
