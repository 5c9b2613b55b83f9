"""Single trajectories as NumPy arrays: dtypes, shapes, the conservation
laws of the collision map, and invalid launches."""

import math

import numpy as np
import pytest

import spinball as sb

FIELDS = ["time", "x", "y", "vx", "vy", "u", "s", "v_par", "q"]


def test_arrays_have_one_entry_per_collision():
    b = sb.Billiard(sb.Stadium(1.0), 0.5)
    t = b.trajectory(1000, (0.1, 0.2), (0.6, 0.7), spin=0.3)
    assert len(t) == 1000
    for name in FIELDS:
        a = getattr(t, name)
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (1000,)
    assert t.wall.dtype == np.int64 and t.wall.shape == (1000,)
    assert set(np.unique(t.wall)) <= {0, 1, 2, 3}  # the stadium's four walls
    assert t.start == (0.1, 0.2, 0.6, 0.7, 0.3)
    assert np.all(np.diff(t.time) > 0)
    d = t.to_dict()
    assert sorted(d) == sorted(FIELDS + ["wall"])
    assert np.array_equal(d["x"], t.x)


def test_energy_and_q_are_conserved():
    alpha = 0.4
    b = sb.Billiard("stadium:a=1", alpha)
    t = b.trajectory(20_000, (0.0, 0.0), (0.6, 0.7), spin=0.3)
    e0 = 0.5 * (0.6**2 + 0.7**2) + 0.5 * alpha * 0.3**2
    e = 0.5 * (t.vx**2 + t.vy**2) + 0.5 * alpha * t.u**2
    # The Rust engine keeps |V| on the launch shell to a few ulps forever.
    assert np.max(np.abs(e - e0)) < 1e-14
    assert b.energy(0.6, 0.7, 0.3) == pytest.approx(e0, rel=1e-15)
    # Q = v_par - alpha u before each collision equals the recorded q.
    u_before = np.concatenate([[0.3], t.u[:-1]])
    assert np.allclose(t.q, t.v_par - alpha * u_before, rtol=0, atol=1e-14)


def test_specular_circle_keeps_the_angle_of_incidence():
    # In a circle with alpha = 0 every collision has the same |v_par|
    # (angular momentum), and every contact lies on the circle.
    b = sb.Billiard(sb.Circle(2.0), 0.0)
    t = b.trajectory(5000, (0.3, -0.4), (0.8, 0.6))
    assert np.allclose(np.hypot(t.x, t.y), 2.0, rtol=0, atol=1e-12)
    assert np.ptp(np.abs(t.v_par)) < 1e-12
    assert np.all(t.u == 0.0)


def test_initial_states_are_the_ensemble_draws():
    alpha = 0.5
    b = sb.Billiard(sb.Sinai(), alpha)
    z = b.initial_states(100, seed=3)
    assert z.shape == (100, 5) and z.dtype == np.float64
    energy = 0.5 * (z[:, 2] ** 2 + z[:, 3] ** 2) + 0.5 * alpha * z[:, 4] ** 2
    assert np.allclose(energy, 0.5, rtol=0, atol=1e-15)
    assert all(sb.Sinai().contains(x, y) for x, y in z[:, :2])
    # Index i does not depend on the others: a shard draws the same states.
    assert np.array_equal(b.initial_states(10, seed=3, first_index=90), z[90:])
    micro = b.initial_states(10, seed=3, sampler="microcanonical")
    assert not np.array_equal(micro, z[:10])


@pytest.mark.parametrize(
    "call, error, words",
    [
        (lambda b: b.trajectory(0, (0, 0), (1, 0)), ValueError, "collisions"),
        (lambda b: b.trajectory(-5, (0, 0), (1, 0)), ValueError, "collisions"),
        (lambda b: b.trajectory(10, (5, 0), (1, 0)), ValueError, "outside"),
        (lambda b: b.trajectory(10, (0, 0), (0, 0)), ValueError, "rest"),
        (lambda b: b.trajectory(10, (0, float("nan")), (1, 0)), ValueError, "finite"),
        (lambda b: b.trajectory(10, (0, 0), (1, 0), spin=float("inf")), ValueError, "finite"),
        (lambda b: b.trajectory(10, (0, 0, 0), (1, 0)), ValueError, "position"),
        (lambda b: b.initial_states(5, sampler="uniform"), ValueError, "sampler"),
        (lambda b: b.initial_states(-1), ValueError, "n must be"),
    ],
)
def test_invalid_launches_raise(call, error, words):
    b = sb.Billiard(sb.Stadium(1.0), 0.5)
    with pytest.raises(error) as info:
        call(b)
    assert words in str(info.value)


@pytest.mark.parametrize("alpha", [-0.1, 1.5, float("nan"), float("inf")])
def test_invalid_alpha_raises(alpha):
    with pytest.raises(ValueError, match="alpha"):
        sb.Billiard(sb.Stadium(), alpha)


def test_extended_alpha_needs_the_flag():
    with pytest.raises(ValueError, match="extended=True"):
        sb.Billiard(sb.Stadium(), 2.0)
    b = sb.Billiard(sb.Stadium(), 2.0, extended=True)
    assert (b.alpha, b.extended) == (2.0, True)
    assert repr(b) == "Billiard(Stadium(a=1.0), alpha=2.0, extended=True)"
    assert math.isfinite(b.trajectory(100, (0, 0), (0.6, 0.7), spin=0.1).x[-1])
