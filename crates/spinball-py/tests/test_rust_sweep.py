"""For the same arguments the Python result equals the JSON of the
command line's `spinball sweep`, number for number (bitwise: JSON floats
are printed shortest-round-trip and read back exactly).

The `spinball` binary is found through the environment variable SPINBALL
(CI points it at target/debug/spinball, built by `cargo test` in the
optimised test profile); without it the test runs
`cargo run --release -p spinball-cli --quiet -- sweep` from the repository
root.
"""

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

import spinball as sb

ROOT = Path(__file__).resolve().parents[3]


def run_sweep(tmp_path, args):
    out = tmp_path / "sweep.json"
    exe = os.environ.get("SPINBALL")
    if exe:
        cmd = [exe, "sweep"]
    elif shutil.which("cargo") and (ROOT / "crates" / "spinball-cli").is_dir():
        cmd = ["cargo", "run", "--release", "-p", "spinball-cli", "--quiet", "--", "sweep"]
    else:
        pytest.skip("neither SPINBALL nor cargo and the repository are available")
    subprocess.run(cmd + args + ["--json", str(out)], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)
    return json.loads(out.read_text())


CASES = [
    ("stadium:a=1", [0.0, 0.5], "fd", "paper", 1),
    ("sinai:L=2,R=1", [0.3, 1.0], "tangent", "microcanonical", 9),
]


@pytest.mark.parametrize("spec, alphas, method, sampler, seed", CASES)
def test_python_equals_spinball_sweep(tmp_path, spec, alphas, method, sampler, seed):
    ics, collisions = 48, 1500
    doc = run_sweep(tmp_path, [
        "--table", spec, "--alphas", ",".join(str(a) for a in alphas),
        "--ics", str(ics), "--collisions", str(collisions), "--method", method,
        "--seed", str(seed), "--sampler", sampler,
    ])
    assert (doc["table"], doc["method"], doc["sampler"], doc["seed"]) == (spec, method, sampler, seed)
    results = sb.alpha_sweep(spec, alphas, ics=ics, collisions=collisions, method=method,
                             sampler=sampler, seed=seed)
    assert len(doc["points"]) == len(results) == len(alphas)
    for point, r in zip(doc["points"], results):
        ours = {
            "alpha": r.alpha, "mean": r.mean, "sem": r.sem, "median": r.median,
            "chaotic_fraction": r.chaotic_fraction, "n_ics": r.n_ics,
            "n_collisions": r.collisions_per_ic, "std": r.std,
            "conditional_mean": r.conditional_mean, "collision_rate": r.collision_rate,
        }
        theirs = {k: point[k] for k in ours}
        assert ours == theirs  # exact float equality, every field
        assert doc["delta0"] == r.delta0 and doc["threshold"] == r.threshold
        assert doc["version"] == r.version
