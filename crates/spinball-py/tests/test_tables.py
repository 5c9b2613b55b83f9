"""Tables: parameters, repr, spec strings, and every invalid table raising
ValueError with the Rust constructor's message."""

import math
import pathlib

import numpy as np
import pytest

import spinball as sb


def test_builtin_tables_keep_their_parameters():
    assert sb.Circle().R == 1.0
    assert (sb.Rectangle(2.0, 0.5).L, sb.Rectangle(2.0, 0.5).H) == (2.0, 0.5)
    assert sb.Stadium(a=1.5).a == 1.5
    s = sb.Sinai(L=2.0, R=1.0)
    assert (s.L, s.R) == (2.0, 1.0)
    for t in [sb.Circle(), sb.Rectangle(), sb.Stadium(), sb.Sinai(), sb.SegmentTable.polygon([(0, 0), (1, 0), (0, 1)])]:
        assert isinstance(t, sb.Table)


def test_keywords_are_those_of_the_spec_strings():
    # Sinai(L=2, R=1) is the spec sinai:L=2,R=1, and so on for every table.
    pairs = [
        (sb.Circle(R=2.0), "circle:R=2"),
        (sb.Rectangle(L=1.5, H=0.5), "rectangle:L=1.5,H=0.5"),
        (sb.Stadium(a=0.5), "stadium:a=0.5"),
        (sb.Sinai(L=2.0, R=0.5), "sinai:L=2,R=0.5"),
    ]
    for t, spec in pairs:
        assert t == sb.table(spec)
    # The lower-case keywords of 0.2 still work, with a DeprecationWarning.
    with pytest.warns(DeprecationWarning, match="deprecated"):
        assert sb.Sinai(l=2.0, r=0.5) == sb.Sinai(L=2.0, R=0.5)
    with pytest.warns(DeprecationWarning, match="keyword is R"):
        assert sb.Circle(radius=2.0) == sb.Circle(R=2.0)
    with pytest.warns(DeprecationWarning):
        assert sb.Rectangle(l=1.5, h=0.5) == sb.Rectangle(L=1.5, H=0.5)
    # A keyword twice, or one the class does not have, is a TypeError that
    # names the keywords.
    with pytest.raises(TypeError, match="give L only"):
        sb.Sinai(L=2.0, l=2.0)
    with pytest.raises(TypeError, match="its keywords are L, R"):
        sb.Sinai(side=2.0)


def test_repr_and_spec_round_trip():
    assert repr(sb.Circle(2.0)) == "Circle(R=2.0)"
    assert repr(sb.Rectangle(1.0, 0.5)) == "Rectangle(L=1.0, H=0.5)"
    assert repr(sb.Stadium(1.0)) == "Stadium(a=1.0)"
    assert repr(sb.Sinai(2.0, 1.0)) == "Sinai(L=2.0, R=1.0)"
    for t in [sb.Circle(2.0), sb.Rectangle(1.0, 0.5), sb.Stadium(1.0), sb.Sinai(2.0, 0.3)]:
        back = sb.table(t.spec)
        assert type(back) is type(t)
        assert back == t
    assert sb.Stadium(1.0).spec == "stadium:a=1"
    assert sb.table("sinai") == sb.Sinai(2.0, 1.0)  # missing keys: the paper's values


def test_geometry_is_the_rust_geometry():
    # Stadium a = 1: a 2 x 2 box with two unit half-disks.
    s = sb.Stadium(1.0)
    assert math.isclose(s.area, 4.0 + math.pi, rel_tol=1e-14)
    assert math.isclose(s.perimeter, 4.0 + 2 * math.pi, rel_tol=1e-14)
    assert math.isclose(s.curved_length, 2 * math.pi, rel_tol=1e-14)
    assert s.bounds == (-2.0, -1.0, 2.0, 1.0)
    assert s.contains(0.0, 0.0) and not s.contains(2.5, 0.0)
    assert sb.Sinai().shape == {"sinai": {"l": 2.0, "r": 1.0}}
    assert not sb.Sinai().contains(0.0, 0.0)  # inside the obstacle


def test_segment_tables_from_lines_and_arcs():
    # The L-shaped room of the Rust docs, as a polygon and as explicit walls.
    pts = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    room = sb.SegmentTable.polygon(np.array(pts, dtype=float))
    walls = [sb.Line(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
    same = sb.SegmentTable(walls)
    assert room == same
    assert math.isclose(room.area, 3.0, rel_tol=1e-14)
    assert len(room.outer) == 6 and room.holes == []
    assert room.spec == "segments(6 walls)"
    assert repr(room.outer[0]) == "Line(start=(0.0, 0.0), end=(2.0, 0.0))"
    # A square with a round hole (a Sinai table made of segments).
    hole = [sb.Arc((0.0, 0.0), 0.5, 0.0, -2 * math.pi)]
    square = [sb.Line((-1, -1), (1, -1)), sb.Line((1, -1), (1, 1)), sb.Line((1, 1), (-1, 1)), sb.Line((-1, 1), (-1, -1))]
    sinai = sb.SegmentTable(square, holes=[hole])
    assert math.isclose(sinai.area, 4.0 - math.pi * 0.25, rel_tol=1e-12)
    assert isinstance(sinai.holes[0][0], sb.Arc)
    assert sinai.holes[0][0].sweep == -2 * math.pi


@pytest.mark.parametrize(
    "make, words",
    [
        (lambda: sb.Circle(0.0), "radius"),
        (lambda: sb.Circle(-1.0), "radius"),
        (lambda: sb.Circle(float("nan")), "radius"),
        (lambda: sb.Rectangle(1.0, float("inf")), "finite"),
        (lambda: sb.Stadium(-0.5), "a"),
        (lambda: sb.Sinai(1.0, 2.0), "smaller than the half-side"),
        (lambda: sb.table("hexagon"), "unknown table"),
        (lambda: sb.table("stadium:b=1"), "no parameter"),
        (lambda: sb.table("stadium:a=x"), "key=number"),
        (lambda: sb.Line((0, 0), (0, 0)), "degenerate"),
        (lambda: sb.Line((0, 0), (1, 2, 3)), "expected"),
        (lambda: sb.Arc((0, 0), 1.0, 0.0, 0.0), "sweep"),
        (lambda: sb.Arc((0, 0), -1.0, 0.0, 1.0), "radius"),
        (lambda: sb.SegmentTable([]), "walls"),
        (lambda: sb.SegmentTable.polygon([(0, 0), (1, 0)]), "walls"),
        (lambda: sb.SegmentTable.polygon([(0, 0), (0, 1), (1, 0)]), "counter-clockwise"),  # clockwise
        (lambda: sb.SegmentTable([sb.Line((0, 0), (1, 0)), sb.Line((1, 0), (0, 1)), sb.Line((0, 1), (0, 0.5))]), "open"),
    ],
)
def test_invalid_tables_raise_value_error(make, words):
    with pytest.raises(ValueError) as info:
        make()
    assert words.lower() in str(info.value).lower()


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        sb.SegmentTable([sb.Line((0, 0), (1, 0)), "a wall"])
    with pytest.raises(TypeError):
        sb.Billiard(42, 0.5)
    with pytest.raises(TypeError):
        sb.Table()


TABLES = pathlib.Path(__file__).resolve().parents[3] / "docs" / "tables"


def test_table_files_read_the_command_line_format(tmp_path):
    mushroom = sb.table_file(TABLES / "mushroom.toml")
    assert isinstance(mushroom, sb.SegmentTable)
    # Half disk of radius 1 on a 0.6 x 1 stem.
    assert mushroom.area == pytest.approx(math.pi / 2 + 0.6, abs=1e-12)
    cell = sb.table_file(str(TABLES / "two-disk-cell.json"))
    assert cell.area == pytest.approx(16.0 - 2 * math.pi * 0.36, abs=1e-12)
    assert len(cell.holes) == 2
    builtin = tmp_path / "stadium.toml"
    builtin.write_text('builtin = "stadium:a=1"\n')
    assert sb.table_file(builtin) == sb.Stadium(1.0)
    bad = tmp_path / "bad.toml"
    bad.write_text("polygon = [[0, 0], [1, 0]]\ncolour = 1\n")
    with pytest.raises(ValueError, match="unknown field"):
        sb.table_file(bad)
    with pytest.raises(ValueError, match="cannot read"):
        sb.table_file(tmp_path / "missing.toml")
