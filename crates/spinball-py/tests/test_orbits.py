"""Periodic orbits: the Sinai table's axis orbit turns elliptic at
α = ℓ/(ℓ + 4R) = 1/5 (L = 2, R = 1; closed form in docs/PHASE_SPACE.md)."""

import numpy as np
import pytest

import spinball as sb


def test_sinai_axis_orbit_turns_elliptic_at_one_fifth():
    alphas = np.linspace(0.0, 1.0, 13)
    d = sb.periodic_orbits("sinai:L=2,R=1", 2, list(alphas), precision=1e-9, normal_samples=512)
    assert d["period"] == 2
    axis = [o for o in d["orbits"] if 4 in o["walls"]]
    assert len(axis) == 4  # the disk to each box wall
    o = axis[0]
    assert o["pair_trace"].dtype == np.float64 and o["pair_trace"].shape == (13,)
    # T(0) = 2 + 4ℓ/R = 6 for a point particle.
    assert abs(o["pair_trace"][0] - 6.0) < 1e-12
    assert o["classes"][0] == "hyperbolic" and o["classes"][6] == "elliptic"
    assert np.isnan(o["rotation"][0]) and 0 < o["rotation"][6] < 0.5
    up = [c for c in o["changes"] if c["crossing"] == 2.0][0]
    assert up["error"] <= 1e-9 and abs(up["alpha"] - 0.2) <= up["error"] + 1e-12


def test_bad_arguments_are_value_errors():
    with pytest.raises(ValueError):
        sb.periodic_orbits("stadium:a=1", 2, [])
    with pytest.raises(ValueError):
        sb.periodic_orbits("stadium:a=1", 2, [0.0, 0.5], precision=2.0)


def test_island_sizes_zero_below_the_onset_and_positive_above():
    # Sinai L = 2, R = 1: the axis orbit from s = L (middle of the bottom
    # box wall) is hyperbolic below α* = 1/5 and elliptic above; its island
    # at α = 0.5 is 0.55 ± 0.10 in (s, sin θ) at 41 cells (docs/PHASE_SPACE.md).
    d = sb.island_sizes("sinai:L=2,R=1", 2.0, [0.1, 0.5], cells=21)
    assert d["area"].dtype == np.float64 and d["area"].shape == (2,)
    assert d["classes"] == ["hyperbolic", "elliptic"]
    assert d["area"][0] == 0.0 and d["error"][0] == 0.0
    assert d["area"][1] > 0.2 and d["error"][1] < 0.5 * d["area"][1]
    assert np.isnan(d["s_min"][0]) and d["s_min"][1] < 2.0 < d["s_max"][1]
    assert d["failures"] == [None, None]
    up = [c for c in d["changes"] if c["crossing"] == 2.0][0]
    assert abs(up["alpha"] - 0.2) <= up["error"] + 1e-12
    # The same numbers again.
    again = sb.island_sizes("sinai:L=2,R=1", 2.0, [0.1, 0.5], cells=21)
    assert np.array_equal(d["area"], again["area"])


def test_island_sizes_bad_arguments():
    with pytest.raises(ValueError):
        sb.island_sizes("sinai:L=2,R=1", 2.0, [])
    with pytest.raises(ValueError):
        sb.island_sizes("sinai:L=2,R=1", 2.0, [0.5], cells=20)
