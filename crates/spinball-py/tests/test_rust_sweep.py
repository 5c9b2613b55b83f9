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


def run_spinball(tmp_path, command, args):
    """The text of the --json file of `spinball COMMAND ARGS`."""
    out = tmp_path / f"{command}.json"
    exe = os.environ.get("SPINBALL")
    if exe:
        cmd = [exe, command]
    elif shutil.which("cargo") and (ROOT / "crates" / "spinball-cli").is_dir():
        cmd = ["cargo", "run", "--release", "-p", "spinball-cli", "--quiet", "--", command]
    else:
        pytest.skip("neither SPINBALL nor cargo and the repository are available")
    subprocess.run(cmd + args + ["--json", str(out)], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)
    return out.read_text()


def run_sweep(tmp_path, args):
    return json.loads(run_spinball(tmp_path, "sweep", args))


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
    assert (doc["schema"], doc["kind"]) == (2, "spinball.sweep")
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


def test_read_results_reads_spinball_lyapunov_bit_for_bit(tmp_path):
    """`read_results` reads the command line's result document, every
    number as written, and `write_results` writes it back."""
    text = run_spinball(tmp_path, "lyapunov", [
        "--table", "stadium:a=1", "--alpha", "0.3,0.7", "--ics", "32",
        "--collisions", "800", "--method", "fd", "--seed", "4", "--quiet",
    ])
    results = sb.read_results(text)
    file = json.loads(text)
    assert (file["schema"], file["kind"]) == (2, "spinball.lyapunov")
    assert [r.alpha for r in results] == [0.3, 0.7]
    for r, point in zip(results, file["points"]):
        assert r.to_dict() == point  # exact float equality, every field
        assert list(r.exponents) == [t["exponent"] for t in point["trajectories"]]
    again = sb.read_results(sb.write_results(results))
    assert again == results
    doc = json.loads(sb.write_results(results, pretty=True))
    assert (doc["schema"], doc["kind"], len(doc["points"])) == (2, "spinball.lyapunov", 2)


def test_read_results_refuses_other_versions_and_kinds():
    old = (ROOT / "crates" / "spinball-analysis" / "tests" / "data" / "0.1.0").resolve()
    with pytest.raises(ValueError, match="spinball 0.1.0 with result schema 1"):
        sb.read_results((old / "partial.json").read_text())
    # A finished result of 0.1.0 has today's fields and still loads.
    (r,) = sb.read_results((old / "result.json").read_text())
    assert (r.version, r.n_ics, r.alpha) == ("0.1.0", 4, 0.5)
    with pytest.raises(ValueError, match="not a `spinball.lyapunov`"):
        sb.read_results('{"schema": 2, "kind": "spinball.sweep", "table": "circle", '
                        '"method": "fd", "sampler": "paper", "seed": 1, "delta0": 1e-7, '
                        '"threshold": 0.01, "version": "0.2.0", "points": []}')


def test_to_json_is_the_document_of_spinball_lyapunov(tmp_path):
    """`LyapunovResult.to_json()` is the file `spinball lyapunov --json`
    writes for the same run, number for number (all but the wall time)."""
    args = dict(ics=24, collisions=600, method="fd", seed=2)
    text = run_spinball(tmp_path, "lyapunov", [
        "--table", "sinai:L=2,R=1", "--alpha", "0.5", "--ics", "24",
        "--collisions", "600", "--method", "fd", "--seed", "2", "--quiet",
    ])
    r = sb.lyapunov(sb.Sinai(L=2, R=1), 0.5, **args)
    ours, theirs = json.loads(r.to_json()), json.loads(text)
    for doc in (ours, theirs):
        doc["points"][0].pop("wall_time_s")
    assert ours == theirs


def test_defaults_are_the_same_from_the_command_line_and_python(tmp_path):
    """The same run with every default (method, seed, sampler, threshold,
    engine) gives bitwise the same λ from `spinball lyapunov` and
    `spinball.lyapunov`; only the size is given, to keep the test short."""
    text = run_spinball(tmp_path, "lyapunov", [
        "--table", "stadium:a=1", "--alpha", "0.5", "--ics", "16",
        "--collisions", "500", "--quiet",
    ])
    (cli,) = sb.read_results(text)
    py = sb.lyapunov(sb.Stadium(a=1), 0.5, ics=16, collisions=500)
    assert (cli.method, cli.seed, cli.sampler) == (py.method, py.seed, py.sampler) == (
        "fd", 0, "paper")
    assert (cli.mean, cli.sem) == (py.mean, py.sem)
    assert list(cli.exponents) == list(py.exponents)
