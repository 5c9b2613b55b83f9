"""The Lyapunov spectrum over an ensemble."""

import numpy as np
import pytest

import spinball as sb


def test_exact_spectrum_pairs_and_sums_to_zero():
    # Paper, appendix "Full Lyapunov spectrum": the exact spectrum pairs
    # (lambda_i + lambda_{6-i} = 0, the map preserves |det J| = 1), one
    # exponent is zero (the flow direction). Same check as the Rust doc
    # example of spectrum_ensemble (Sinai L = 2, R = 1, alpha = 0.5).
    s = sb.spectrum(sb.Sinai(), 0.5, ics=8, collisions=5000, seed=1)
    for name in ["mean", "sem", "per_collision_mean"]:
        a = getattr(s, name)
        assert a.dtype == np.float64 and a.shape == (5,)
    assert s.exponents.shape == (8, 5) and s.per_collision.shape == (8, 5)
    assert s.mean[0] > 0.05
    assert abs(s.mean[0] + s.mean[4]) < 0.01
    assert s.sum_max_abs < 1e-9
    assert np.all(np.diff(s.exponents, axis=1) <= 0)  # descending per trajectory
    assert (s.method, s.delta0, s.alpha, s.table, s.n_ics) == ("tangent", None, 0.5, "sinai:L=2,R=1", 8)
    d = s.to_dict()
    assert d["mean"] == list(s.mean) and len(d["spectra"]) == 8
    # Batches (for Ctrl-C) do not change a number: 40 ICs run in 16-IC batches.
    big = sb.spectrum(sb.Sinai(), 0.5, ics=40, collisions=500, seed=1, threads=1)
    parts = [sb.spectrum(sb.Sinai(), 0.5, ics=20, first_index=k, collisions=500, seed=1) for k in (0, 20)]
    assert np.array_equal(big.exponents, np.vstack([p.exponents for p in parts]))


def test_fd_spectrum_and_qr_interval():
    fd = sb.spectrum("stadium:a=1", 0.5, ics=4, collisions=2000, method="fd", seed=2)
    assert fd.method == "fd" and fd.delta0 == 1e-7 and fd.exponents.shape == (4, 5)
    tg = sb.spectrum("stadium:a=1", 0.5, ics=4, collisions=2000, qr_interval=8, seed=2)
    assert tg.qr_interval == 8


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(ics=1), "ics"),
        (dict(collisions=0), "collisions"),
        (dict(qr_interval=0), "qr_interval"),
        (dict(qr_interval=10**6), "qr_interval"),
        (dict(method="fd", qr_interval=2), "qr_interval"),
        (dict(method="nope"), "method"),
        (dict(sampler="nope"), "sampler"),
    ],
)
def test_bad_spectrum_arguments(kwargs, words):
    with pytest.raises(ValueError, match=words):
        sb.spectrum("stadium:a=1", 0.5, **kwargs)


def test_to_json_is_the_document_the_command_line_writes(tmp_path):
    # One schema: to_json() is the `spinball.spectrum` document of
    # `spinball spectrum --json` for the same run (wall time aside).
    import json
    import os
    import shutil
    import subprocess

    s = sb.spectrum("stadium:a=1", 0.5, ics=4, collisions=500, seed=3, method="tangent")
    doc = json.loads(s.to_json())
    assert doc["kind"] == "spinball.spectrum" and doc["schema"] == 2
    assert doc["alphas"] == [0.5] and len(doc["points"]) == 1
    assert doc["points"][0]["mean"] == list(s.mean)
    exe = os.environ.get("SPINBALL") or shutil.which("spinball")
    if exe is None:
        pytest.skip("the spinball command line is not built (set SPINBALL)")
    out = tmp_path / "s.json"
    subprocess.run(
        [exe, "spectrum", "--table", "stadium:a=1", "--alpha", "0.5", "--ics", "4",
         "--collisions", "500", "--seed", "3", "--method", "tangent", "--json", str(out), "--quiet"],
        check=True,
    )
    cli = json.loads(out.read_text())
    for d in (doc, cli):
        for p in d["points"]:
            # The wall time differs, and with it the record's checksum.
            p.pop("wall_time_s", None)
            p.pop("checksum", None)
        d.pop("version", None)
    assert doc == cli
