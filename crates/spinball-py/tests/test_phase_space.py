"""Phase space from Python: sections, FTLE maps, the bouncing-ball
prediction, Kac return times and the invariant-measure sampler, and the
same numbers as the command line's `spinball ftle-map` and `spinball
section` (found through SPINBALL, as in test_rust_sweep.py)."""

import math
import os
import subprocess

import numpy as np
import pytest

import spinball as sb


def test_section_columns_and_slice():
    sec = sb.section("stadium:a=1", 0.5, orbits=3, collisions=40, seed=2)
    assert set(sec) == {"orbit", "s", "sin_theta", "v_par", "speed", "u", "wall", "q"}
    assert all(len(v) == 120 for v in sec.values())
    assert sec["orbit"].dtype == np.int64 and sec["wall"].dtype == np.int64
    assert list(np.unique(sec["orbit"])) == [0, 1, 2]
    assert np.allclose(sec["sin_theta"], sec["v_par"] / sec["speed"])
    # Q = v∥ − αu, and the paper sampler's shell E = ½: |v|² + αu² = 1.
    assert np.allclose(sec["q"], sec["v_par"] - 0.5 * sec["u"])
    assert np.allclose(sec["speed"] ** 2 + 0.5 * sec["u"] ** 2, 1.0, atol=1e-12)
    sliced = sb.section("stadium:a=1", 0.5, orbits=3, collisions=40, seed=2, spin_slice=0.2)
    keep = np.abs(math.sqrt(0.5) * sec["u"]) < 0.2
    assert np.array_equal(sliced["s"], sec["s"][keep])
    inv = sb.section("sinai:L=2,R=1", 0.3, orbits=2, collisions=10, sampler="invariant")
    assert len(inv["s"]) == 20


def test_invariant_states_are_on_the_shell_and_start_the_sections():
    states = sb.invariant_states(sb.Stadium(), 0.5, 400, seed=3)
    assert states.shape == (400, 5)
    x, y, vx, vy, u = states.T
    assert np.allclose(vx**2 + vy**2 + 0.5 * u**2, 1.0, atol=1e-12)
    # Streams by index: a later block is the tail of a longer draw.
    tail = sb.invariant_states(sb.Stadium(), 0.5, 100, seed=3, first_index=300)
    assert np.array_equal(tail, states[300:])
    # The measure is uniform in the disk of (v∥, √α u): E[w²] = 1/4 for
    # w = √α u (uniform disk of radius 1); 400 draws, SEM ≈ 0.22/√400 ≈ 0.011.
    w2 = 0.5 * u**2
    assert abs(w2.mean() - 0.25) < 0.05
    assert sb.invariant_states("circle", 0.0, 0).shape == (0, 5)


def test_ftle_map_island_is_predicted_and_regular():
    m = sb.ftle_map("stadium:a=1", 0.5, columns=32, rows=16, collisions=1000, seed=5)
    assert m["exponents"].shape == (16, 32) and m["s"].shape == (32,) and m["row"].shape == (16,)
    assert m["slice"] == "spin" and m["slice_value"] == 0.0 and m["table"] == "stadium:a=1"
    assert m["on_shell"] == 16 * 32 and not np.isnan(m["exponents"]).any()
    assert m["predicted"].dtype == np.bool_ and m["predicted"].shape == (16, 32)
    # The library's island-map test: every predicted cell is regular.
    assert m["predicted_cells"] > 0 and m["predicted_regular"] == m["predicted_cells"]
    assert np.all(m["exponents"][m["predicted"]] <= m["threshold"])
    assert m["regular"] == int((m["exponents"] <= 0.01).sum())
    # The circle is integrable: every cell regular, no flats to predict.
    c = sb.ftle_map(sb.Circle(), 0.5, columns=6, rows=6, spin=0.2, collisions=500)
    assert c["regular_fraction"] == 1.0 and c["predicted"] is None


def test_ftle_map_at_fixed_q_has_cells_off_the_shell():
    m = sb.ftle_map("sinai:L=2,R=1", 0.5, columns=8, rows=8, q=0.3, collisions=200)
    off = np.isnan(m["exponents"])
    assert off.any() and not off.all()
    assert m["on_shell"] == int((~off).sum()) and m["slice"] == "q"


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(spin=0.1, q=0.2), "not both"),
        (dict(spin=2.0), "αu²"),
        (dict(columns=0), "columns"),
        (dict(collisions=0), "collisions"),
        (dict(threshold=float("nan")), "threshold"),
    ],
)
def test_bad_ftle_map_arguments(kwargs, words):
    with pytest.raises(ValueError, match=words):
        sb.ftle_map("stadium:a=1", 0.5, **kwargs)


def test_q_slice_needs_spin():
    with pytest.raises(ValueError, match="α > 0"):
        sb.ftle_map("stadium:a=1", 0.0, q=0.1)


def test_kac_ratio_is_one_on_the_ergodic_stadium():
    # The library's doc example: bottom flat, |v∥| < ½, 8 orbits × 20 000
    # collisions, seed 1; Kac's 1/μ(A) = 2|∂Q|/2 and a ratio within 0.1 of 1.
    k = sb.kac("stadium:a=1", 0.0, s=(0.0, 2.0), v_par=(-0.5, 0.5), orbits=8, collisions=20_000, seed=1)
    assert abs(k["expected"] - (4 + 2 * math.pi)) < 1e-12
    assert abs(k["ratio"] - 1) < 0.1 and k["ratio_sem"] > 0
    assert k["index"].tolist() == list(range(8)) and k["never_returned"] == 0
    assert np.allclose(k["orbit_ratio"], k["orbit_mean_return"] / k["expected"])
    with pytest.raises(ValueError, match="zero invariant measure"):
        sb.kac("stadium:a=1", 0.0, s=(0.0, 2.0), w=(0.2, 0.4))
    with pytest.raises(ValueError, match="s:"):
        sb.kac("stadium:a=1", 0.5, s=(2.0, 1.0))
    with pytest.raises(ValueError, match="orbits"):
        sb.kac("stadium:a=1", 0.5, s=(0.0, 2.0), orbits=1)


def test_bouncing_ball_prediction():
    assert sb.pair_rotation(1.0) == pytest.approx(math.pi)
    assert sb.pair_rotation(0.0) == 0.0
    with pytest.raises(ValueError):
        sb.pair_rotation(float("nan"))
    # Nearly vertical with little spin between the flats: trapped; in a cap
    # or moving along the flats: not (the library's unit test cases).
    states = np.array([[0, 0, 0.05, 0.9, 0.1], [1.5, 0, 0.05, 0.9, 0.1], [0, 0, 1, 0, 0]])
    assert sb.bouncing_ball(sb.Stadium(), 0.5, states).tolist() == [True, False, False]
    assert sb.bouncing_ball(sb.Stadium(), 0.5, states[0]).tolist() == [True]
    with pytest.raises(ValueError, match="stadium"):
        sb.bouncing_ball("sinai:L=2,R=1", 0.5, states)


def spinball_cli():
    exe = os.environ.get("SPINBALL")
    if not exe:
        pytest.skip("SPINBALL (the spinball binary) is not set")
    return exe


def test_the_command_line_gives_the_same_map_and_section(tmp_path):
    exe = spinball_cli()
    npy = tmp_path / "map.npy"
    subprocess.run(
        [exe, "ftle-map", "--table", "stadium:a=1", "--alpha", "0.5", "--columns", "12",
         "--rows", "10", "--q", "0.1", "--collisions", "300", "--seed", "4", "--npy", str(npy),
         "--quiet"],
        check=True,
    )
    m = sb.ftle_map("stadium:a=1", 0.5, columns=12, rows=10, q=0.1, collisions=300, seed=4)
    # Bitwise: a table given to the command line as a spec runs as `Built`,
    # which measures tangent vectors in the table's own unit length, as the
    # `Table` the Python package runs does.
    assert np.array_equal(np.load(npy), m["exponents"], equal_nan=True)
    sec_npy = tmp_path / "section.npy"
    subprocess.run(
        [exe, "section", "--table", "sinai:L=2,R=1", "--alpha", "0.3", "--orbits", "2",
         "--collisions", "25", "--seed", "4", "--sampler", "invariant", "--npy", str(sec_npy),
         "--quiet"],
        check=True,
    )
    sec = sb.section("sinai:L=2,R=1", 0.3, orbits=2, collisions=25, seed=4, sampler="invariant")
    cli = np.load(sec_npy)
    for k, name in enumerate(["orbit", "s", "sin_theta", "v_par", "speed", "u", "wall", "q"]):
        assert np.array_equal(cli[:, k], sec[name])
