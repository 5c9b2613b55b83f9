"""The typed surface: every public name and attribute has a stub, and the
docstrings tell units, defaults and errors."""

import inspect
from pathlib import Path

import spinball as sb

STUB = (Path(sb.__file__).parent / "_spinball.pyi").read_text()
CLASSES = [sb.Table, sb.Circle, sb.Rectangle, sb.Stadium, sb.Sinai, sb.SegmentTable, sb.Line,
           sb.Arc, sb.Billiard, sb.Trajectory, sb.FtleDistribution, sb.LyapunovResult,
           sb.SpectrumResult]


def test_every_public_name_and_attribute_has_a_stub():
    assert [n for n in sb.__all__ if n not in STUB] == []
    for cls in CLASSES:
        assert f"class {cls.__name__}" in STUB
        public = [a for a in vars(cls) if not a.startswith("_")]
        assert [a for a in public if a not in STUB] == [], cls.__name__


def test_docstrings_give_units_defaults_and_errors():
    doc = sb.lyapunov.__doc__
    for words in ["per unit time", "default 1000", "10 000", "1e-7", "ValueError",
                  "RuntimeError", "KeyboardInterrupt", "GIL"]:
        assert words in doc, words
    assert "threshold=0.01" in str(inspect.signature(sb.lyapunov))
    for f in [sb.alpha_sweep, sb.spectrum, sb.table]:
        assert "ValueError" in f.__doc__
    for cls in CLASSES:
        assert cls.__doc__ and len(cls.__doc__) > 40, cls.__name__
