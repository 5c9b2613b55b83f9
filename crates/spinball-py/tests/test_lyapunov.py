"""Ensemble estimates: the paper's published numbers with fixed seeds,
the result object (fields, arrays, JSON), reproducibility, stop rules,
progress, and every invalid argument raising."""

import json
import math

import numpy as np
import pytest

import spinball as sb


def within(value, sem, paper, paper_sem, k=3.0):
    """|value - paper| within k combined standard errors."""
    return abs(value - paper) <= k * math.hypot(sem, paper_sem)


# Paper (Lund, Murugan, Shock, arXiv:2505.15335 v2), Table I, column 10^4
# collisions, paper sampler, finite differences with delta0 = 1e-7 (the
# numbers crates/spinball-analysis/src/diagnostics/paper.rs stores). Their SEMs are over
# 10^4 ICs; ours, over fewer ICs, dominate the tolerance of 3 combined SEMs.
TABLE_I_1E4 = [
    ("stadium:a=1", 0.1, 0.281, 0.0005),
    ("stadium:a=1", 0.5, 0.183, 0.001),
    ("stadium:a=1", 1.0, 0.147, 0.001),
    ("sinai:L=2,R=1", 0.5, 0.120, 0.0005),
    ("sinai:L=2,R=1", 1.0, 0.103, 0.0005),
]


@pytest.mark.parametrize("spec, alpha, paper, paper_sem", TABLE_I_1E4)
def test_table_i(spec, alpha, paper, paper_sem):
    r = sb.lyapunov(spec, alpha, ics=1500, collisions=10_000, seed=1)
    assert r.n_ics == 1500 and r.sem < 0.006
    assert within(r.mean, r.sem, paper, paper_sem), (r.mean, r.sem, paper)


def test_specular_stadium_and_chaotic_fraction():
    # Paper §IV: lambda(0) ~ 0.43 for the stadium; §VI: at alpha = 0 every
    # trajectory is chaotic, at alpha = 1 "~90%" for the stadium (FTLE >
    # 0.01, 5e4 collisions; docs/REPRODUCTION.md measures 91.3 +- 0.6%).
    r0 = sb.lyapunov(sb.Stadium(1.0), 0.0, ics=500, collisions=10_000, seed=2)
    assert abs(r0.mean - 0.43) < 0.02
    assert r0.chaotic_fraction == 1.0
    r1 = sb.lyapunov(sb.Stadium(1.0), 1.0, ics=1000, collisions=50_000, seed=2)
    assert abs(r1.chaotic_fraction - 0.90) < 0.03 + 3 * r1.chaotic_fraction_sem


def test_tangent_and_fd_agree_and_integrable_tables_are_regular():
    fd = sb.lyapunov("stadium:a=1", 0.4, ics=600, collisions=5000, seed=3, method="fd")
    tg = sb.lyapunov("stadium:a=1", 0.4, ics=600, collisions=5000, seed=3, method="tangent")
    assert within(fd.mean, fd.sem, tg.mean, tg.sem)
    assert (fd.method, fd.delta0, tg.method, tg.delta0) == ("fd", 1e-7, "tangent", None)
    # Paper §IV: lambda ~ 0.20 for the solid sphere (alpha = 2/5).
    assert abs(tg.mean - 0.20) < 0.02
    # Circle: integrable, FTLE ~ ln t / t -> small (paper: consistent with 0).
    c = sb.lyapunov(sb.Circle(), 0.5, ics=64, collisions=20_000, seed=3, method="tangent")
    assert 0 <= c.mean < 0.01 and c.chaotic_fraction == 0.0 and c.conditional_mean is None


def test_result_fields_arrays_and_json():
    r = sb.lyapunov(sb.Sinai(), 0.5, ics=100, collisions=2000, seed=4, first_index=10)
    for name, dtype in [("exponents", np.float64), ("per_collision", np.float64),
                        ("times", np.float64), ("collisions", np.int64), ("indices", np.int64)]:
        a = getattr(r, name)
        assert isinstance(a, np.ndarray) and a.dtype == dtype and a.shape == (100,), name
    assert np.array_equal(r.indices, np.arange(10, 110))
    assert np.all(r.collisions == 2000)
    assert r.mean == np.mean(r.exponents) or math.isclose(r.mean, np.mean(r.exponents), rel_tol=1e-13)
    assert r.median == np.median(r.exponents)
    assert math.isclose(r.sem, np.std(r.exponents, ddof=1) / 10.0, rel_tol=1e-12)
    assert r.chaotic_fraction == np.mean(r.exponents > 0.01)
    assert math.isclose(r.collision_rate, 2000 * 100 / np.sum(r.times), rel_tol=1e-13)
    assert (r.table, r.alpha, r.seed, r.sampler, r.engine, r.stop) == (
        "sinai:L=2,R=1", 0.5, 4, "paper", "lanes", "completed")
    assert (r.n_ics, r.first_index, r.collisions_per_ic, r.threshold) == (100, 10, 2000, 0.01)
    assert r.wall_time_s > 0 and r.version == sb.__version__
    # to_json is the command line's result document; to_dict its one point,
    # the Rust result's serde JSON, field for field.
    d = r.to_dict()
    doc = json.loads(r.to_json())
    assert (doc["schema"], doc["kind"]) == (2, "spinball.lyapunov")
    assert d == doc["points"][0] == json.loads(r.to_json(indent=2))["points"][0]
    # The bare result spinball 0.2's to_json wrote still reads.
    assert sb.LyapunovResult.from_json(json.dumps(d)) == r
    assert sb.read_results(json.dumps(d)) == [r]
    assert d["mean"] == r.mean and d["sem"] == r.sem and d["median"] == r.median
    assert d["method"] == {"finite_difference": {"delta0": 1e-7}}
    assert d["table"] == {"name": "sinai:L=2,R=1", "shape": {"sinai": {"l": 2.0, "r": 1.0}}}
    assert [t["exponent"] for t in d["trajectories"]] == list(r.exponents)
    assert sb.LyapunovResult.from_json(r.to_json()) == r
    p = r.provenance
    assert (p["alpha"], p["seed"], p["collisions_per_ic"], p["engine"], p["version"]) == (
        0.5, 4, 2000, "lanes", sb.__version__)
    assert f"λ = {sb.plus_minus(r.mean, r.sem)} " in repr(r)
    f = r.ftle()
    assert np.array_equal(f.exponents, r.exponents) and f.median == r.median


def test_bitwise_reproducible_across_threads_shards_and_engines():
    kw = dict(ics=200, collisions=3000, seed=5, method="tangent")
    all_cores = sb.lyapunov("stadium:a=1", 0.5, **kw)
    one = sb.lyapunov("stadium:a=1", 0.5, threads=1, **kw)
    assert np.array_equal(all_cores.exponents, one.exponents)
    assert (all_cores.mean, all_cores.sem) == (one.mean, one.sem)
    a = sb.lyapunov("stadium:a=1", 0.5, ics=80, collisions=3000, seed=5, method="tangent")
    b = sb.lyapunov("stadium:a=1", 0.5, ics=120, first_index=80, collisions=3000, seed=5, method="tangent")
    merged = a.merge(b)
    assert np.array_equal(merged.exponents, one.exponents) and merged.mean == one.mean
    scalar = sb.lyapunov("stadium:a=1", 0.5, engine="scalar", **kw)
    assert scalar.engine == "scalar"
    assert np.allclose(scalar.exponents, one.exponents, rtol=1e-9, atol=1e-12)
    with pytest.raises(ValueError, match="adjacent"):
        a.merge(a)


def test_explicit_initial_states_and_segment_tables():
    b = sb.Billiard(sb.Stadium(), 0.5)
    z = b.initial_states(50, seed=6)
    r = sb.lyapunov(sb.Stadium(), 0.5, initial_states=z, collisions=2000, seed=6)
    assert (r.n_ics, r.sampler) == (50, None)
    bad = z.copy()
    bad[7, 0] = 10.0  # outside the table
    with pytest.raises(ValueError, match="initial condition 7"):
        sb.lyapunov(sb.Stadium(), 0.5, initial_states=bad, collisions=100)
    room = sb.SegmentTable.polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    e = sb.lyapunov(room, 0.5, ics=16, collisions=2000, seed=1, method="tangent")
    assert e.engine == "lanes" and e.table == "segments(6 walls)" and e.sem > 0


def test_stop_rule_and_progress_events():
    events = []
    r = sb.lyapunov("stadium:a=1", 0.0, ics=5000, collisions=2000, seed=7,
                    target_rel_sem=0.02, batch=32, progress=events.append)
    assert r.stop == "target_reached" and r.n_ics < 5000 and r.rel_sem <= 0.02
    kinds = [e["event"] for e in events]
    assert kinds[0] == "started" and kinds[-1] == "finished"
    batches = [e for e in events if e["event"] == "batch"]
    assert [e["ics_done"] for e in batches] == list(range(32, r.n_ics + 1, 32))
    assert batches[-1]["mean"] == r.mean and batches[-1]["target_rel_sem"] == 0.02


def test_progress_true_prints_and_a_raising_callback_stops_the_run(capsys):
    sb.lyapunov("stadium:a=1", 0.5, ics=128, collisions=500, progress=True)
    err = capsys.readouterr().err
    assert "done: λ =" in err
    # Not a terminal (captured): one line per point, no carriage returns.
    assert "\r" not in err and err.count("\n") == 1, repr(err)

    class Stop(Exception):
        pass

    def stop_at_second_batch(event):
        if event["event"] == "batch" and event["ics_done"] >= 64:
            raise Stop("enough")

    with pytest.raises(Stop):
        sb.lyapunov("stadium:a=1", 0.5, ics=10_000, collisions=500, batch=32,
                    target_rel_sem=0.0, progress=stop_at_second_batch)


def test_alpha_sweep_equals_single_runs():
    alphas = np.linspace(0.0, 1.0, 3)
    rs = sb.alpha_sweep(sb.Sinai(), alphas, ics=64, collisions=2000, seed=8)
    assert [r.alpha for r in rs] == list(alphas)
    for r in rs:
        single = sb.lyapunov(sb.Sinai(), r.alpha, ics=64, collisions=2000, seed=8)
        assert np.array_equal(r.exponents, single.exponents) and r.mean == single.mean
    ext = sb.alpha_sweep(sb.Sinai(), [2.0], ics=8, collisions=500, extended=True)
    assert ext[0].alpha == 2.0


BAD = [
    (lambda: sb.lyapunov("stadium", 1.5), ValueError, "extended=True"),
    (lambda: sb.lyapunov("stadium", -0.5), ValueError, "alpha"),
    (lambda: sb.lyapunov("stadium", float("nan")), ValueError, "alpha"),
    (lambda: sb.lyapunov("stadium", 0.5, ics=1), ValueError, "ics"),
    (lambda: sb.lyapunov("stadium", 0.5, ics=-3), ValueError, "ics"),
    (lambda: sb.lyapunov("stadium", 0.5, collisions=0), ValueError, "collisions"),
    (lambda: sb.lyapunov("stadium", 0.5, method="euler"), ValueError, "method"),
    (lambda: sb.lyapunov("stadium", 0.5, delta0=-1e-7), ValueError, "delta0"),
    (lambda: sb.lyapunov("stadium", 0.5, delta0=float("nan")), ValueError, "delta0"),
    (lambda: sb.lyapunov("stadium", 0.5, method="tangent", delta0=1e-7), ValueError, "delta0"),
    (lambda: sb.lyapunov("stadium", 0.5, sampler="uniform"), ValueError, "sampler"),
    (lambda: sb.lyapunov("stadium", 0.5, threads=0), ValueError, "threads"),
    (lambda: sb.lyapunov("stadium", 0.5, engine="gpu"), ValueError, "engine"),
    (lambda: sb.lyapunov("stadium", 0.5, threshold=float("inf")), ValueError, "threshold"),
    (lambda: sb.lyapunov("stadium", 0.5, first_index=-1), ValueError, "first_index"),
    (lambda: sb.lyapunov("stadium", 0.5, target_rel_sem=-0.1), ValueError, "target_rel_sem"),
    (lambda: sb.lyapunov("stadium", 0.5, target_rel_sem=0.1, batch=1), ValueError, "batch"),
    (lambda: sb.lyapunov("stadium", 0.5, time_budget=-1.0), ValueError, "time_budget"),
    (lambda: sb.lyapunov("stadium", 0.5, initial_states=np.zeros((4, 3))), ValueError, "(n, 5)"),
    (lambda: sb.lyapunov("stadium", 0.5, initial_states=np.zeros((4, 5))), ValueError, "rest"),
    (lambda: sb.lyapunov("stadium", 0.5, initial_states=np.full((4, 5), 0.1), ics=10), ValueError, "states given"),
    (lambda: sb.lyapunov("stadium", 0.5, initial_states=np.full((4, 5), 0.1), sampler="paper"), ValueError, "either"),
    (lambda: sb.lyapunov("triangle", 0.5), ValueError, "unknown table"),
    (lambda: sb.lyapunov(3.0, 0.5), TypeError, "table"),
    (lambda: sb.lyapunov("stadium", 0.5, progress="yes"), TypeError, "progress"),
    (lambda: sb.alpha_sweep("stadium", []), ValueError, "no points"),
    (lambda: sb.alpha_sweep("stadium", [0.5, 1.2]), ValueError, "alpha"),
    (lambda: sb.FtleDistribution([]), ValueError, "at least one"),
    (lambda: sb.FtleDistribution([0.1, float("nan")]), ValueError, "not finite"),
    (lambda: sb.FtleDistribution([0.1, 0.2]).quantile(1.5), ValueError, "[0, 1]"),
    (lambda: sb.FtleDistribution([0.1, 0.2]).histogram(bins=0), ValueError, "bins"),
    (lambda: sb.FtleDistribution([0.1, 0.2]).histogram(range=(1.0, 0.0)), ValueError, "lo < hi"),
    (lambda: sb.LyapunovResult.from_json("{}"), ValueError, "LyapunovResult"),
]


@pytest.mark.parametrize("call, error, words", BAD)
def test_bad_input_raises(call, error, words):
    with pytest.raises(error) as info:
        call()
    assert words in str(info.value)


def test_ftle_distribution_statistics():
    f = sb.FtleDistribution([0.0, 0.005, 0.15, 0.25, 0.45])
    assert f.mean == pytest.approx(0.171) and f.median == 0.15 and len(f) == 5
    assert f.quantile(0.25) == np.quantile(f.exponents, 0.25)
    frac, sem = f.chaotic_fraction()
    assert frac == 0.6 and sem == pytest.approx(math.sqrt(0.6 * 0.4 / 5))
    assert f.conditional_mean() == pytest.approx(0.85 / 3)
    assert f.dhf_product() == pytest.approx(0.171 * 0.6)
    counts, edges = f.histogram(bins=4, range=(0.0, 0.4))
    assert counts.dtype == np.int64 and edges.dtype == np.float64
    assert list(counts) == [2, 1, 1, 0]  # 0.45 lies outside [0, 0.4)
    assert np.allclose(edges, [0.0, 0.1, 0.2, 0.3, 0.4])
    auto_counts, _ = f.histogram(bins=3)
    assert auto_counts.sum() == 5  # the default range holds every value
    band = f.chaotic_fraction_band()
    assert list(band["thresholds"]) == sb.THRESHOLD_BAND
    # Thresholds 0.001, 0.002 count 0.005 as chaotic; 0.005 and above do not.
    assert list(band["fractions"]) == [0.8, 0.8, 0.6, 0.6, 0.6, 0.6]
    assert (band["min"], band["max"]) == (0.6, 0.8) and band["spread"] == pytest.approx(0.2)


def test_values_print_with_the_digits_their_error_shows():
    # Two significant digits of the error, the value to the same place.
    assert sb.plus_minus(0.0003124, 0.0000412) == "0.000312 ± 0.000041"
    assert sb.plus_minus(0.18654, 0.00381) == "0.1865 ± 0.0038"
    assert sb.plus_minus(0.5, 0.0) == "0.5 ± 0"
