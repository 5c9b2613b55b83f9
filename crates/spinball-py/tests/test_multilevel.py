"""Multilevel ensembles over run length from Python: the estimate agrees
with a plain ensemble of the same run length, carries its error budget,
and every invalid argument raises."""

import math

import pytest

import spinball as sb


def test_multilevel_agrees_with_plain():
    # Stadium a = 1, alpha = 0.5, tangent: levels 250 ... 2000 collisions.
    ml = sb.lyapunov(
        "stadium:a=1", 0.5, collisions=2000, method="tangent", seed=3,
        estimator="multilevel", target_error=0.02,
    )
    assert isinstance(ml, sb.MultilevelResult)
    plain = sb.lyapunov(
        "stadium:a=1", 0.5, ics=1500, collisions=2000, method="tangent", seed=4,
    )
    # Independent seeds: within 3 combined standard errors.
    assert abs(ml.mean - plain.mean) < 3 * math.hypot(ml.sem, plain.sem)
    assert ml.target_met and ml.total_error >= ml.sem
    assert [lv["collisions"] for lv in ml.levels] == [250, 500, 1000, 2000]
    # The long level needs fewer initial conditions than the short one.
    assert ml.levels[-1]["n_ics"] < ml.levels[0]["n_ics"]
    assert 0.8 < ml.chaotic_fraction <= 1.0 and ml.chaotic_mean > ml.mean
    assert ml.bias_law in ("1/T", "ln T / T", "neither")
    assert "chaotic fraction" in str(ml)


def test_multilevel_refuses_bad_arguments():
    with pytest.raises(ValueError, match="target_error"):
        sb.lyapunov("stadium:a=1", 0.5, collisions=2000, estimator="multilevel")
    with pytest.raises(ValueError, match="target_error"):
        sb.lyapunov("stadium:a=1", 0.5, collisions=2000, target_error=0.01)
    with pytest.raises(ValueError, match="estimator"):
        sb.lyapunov("stadium:a=1", 0.5, estimator="fancy")
    with pytest.raises(ValueError, match="four levels"):
        sb.lyapunov(
            "stadium:a=1", 0.5, collisions=1000,
            estimator="multilevel", target_error=0.01,
        )
    with pytest.raises(ValueError):
        sb.lyapunov(
            "stadium:a=1", 0.5, collisions=2000, time_budget=1.0,
            estimator="multilevel", target_error=0.01,
        )
