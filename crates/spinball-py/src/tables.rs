//! The table classes: `Circle`, `Rectangle`, `Stadium`, `Sinai` and
//! `SegmentTable` (from `Line` and `Arc` walls), all subclasses of `Table`.
//!
//! Each class validates through the Rust constructor (its message becomes a
//! `ValueError`) and keeps the Rust table. Runs dispatch once on
//! [`AnyTable`] and then call the generic analysis with the concrete table
//! ([`with_table!`](crate::with_table)); the built-in tables run as the
//! `Table` enum, exactly as the Rust `sweep` example runs them.

use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::exceptions::{PyDeprecationWarning, PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};
use spinball_geometry::{
    ArcSegment, Boundary, Built, Circle, DVec2, LineSegment, Rectangle, Segment, SegmentTable,
    Sinai, Stadium, Table, TableFile, ToOutline,
};

use crate::args::{pair, rows};
use crate::errors::{geometry, value_error};

/// A table of any kind the Python classes make.
#[derive(Debug, Clone, PartialEq)]
pub enum AnyTable {
    /// A built-in table.
    Builtin(Table),
    /// A table built from walls.
    Segments(SegmentTable),
}

/// Evaluate `$body` with `$t` bound to the concrete table of an
/// [`AnyTable`] (one dispatch, then static).
#[macro_export]
macro_rules! with_table {
    ($table:expr, |$t:ident| $body:expr) => {
        match $table {
            $crate::tables::AnyTable::Builtin($t) => $body,
            $crate::tables::AnyTable::Segments($t) => $body,
        }
    };
}

impl From<Built> for AnyTable {
    fn from(b: Built) -> Self {
        match b {
            Built::Table(t) => AnyTable::Builtin(t),
            Built::Segments(t) => AnyTable::Segments(t),
        }
    }
}

impl From<AnyTable> for Built {
    fn from(t: AnyTable) -> Self {
        match t {
            AnyTable::Builtin(t) => Built::Table(t),
            AnyTable::Segments(t) => Built::Segments(t),
        }
    }
}

impl AnyTable {
    /// The spec string (`stadium:a=1`, `segments(6 walls)`).
    #[must_use]
    pub fn spec(&self) -> String {
        with_table!(self, |t| t
            .shape()
            .map(|s| s.to_string())
            .unwrap_or_default())
    }

    /// How the table prints in Python.
    #[must_use]
    pub fn repr(&self) -> String {
        match self {
            AnyTable::Builtin(Table::Circle(c)) => format!("Circle(R={:?})", c.radius()),
            AnyTable::Builtin(Table::Rectangle(r)) => {
                format!("Rectangle(L={:?}, H={:?})", r.l(), r.h())
            }
            AnyTable::Builtin(Table::Stadium(s)) => format!("Stadium(a={:?})", s.a()),
            AnyTable::Builtin(Table::Sinai(s)) => format!("Sinai(L={:?}, R={:?})", s.l(), s.r()),
            AnyTable::Segments(s) => format!(
                "SegmentTable(<{} walls, {} holes>)",
                s.walls().len(),
                s.holes().len()
            ),
        }
    }
}

/// The table argument of a function: a table object or a spec string.
pub fn table_arg(obj: &Bound<'_, PyAny>) -> PyResult<AnyTable> {
    if let Ok(t) = obj.cast::<PyTable>() {
        return Ok(t.get().inner.clone());
    }
    if let Ok(s) = obj.cast::<PyString>() {
        let spec: String = s.extract()?;
        return spec
            .parse::<Built>()
            .map(AnyTable::from)
            .map_err(|e| value_error(format!("table spec `{spec}`: {e}")));
    }
    Err(PyTypeError::new_err(format!(
        "table: expected a spinball table (Circle, Rectangle, Stadium, Sinai, SegmentTable) \
         or a spec string such as 'stadium:a=1', got {}",
        obj.get_type().name()?
    )))
}

/// A billiard table (the base class of `Circle`, `Rectangle`, `Stadium`,
/// `Sinai` and `SegmentTable`; lengths in the paper's units).
#[pyclass(frozen, subclass, name = "Table", module = "spinball")]
pub struct PyTable {
    pub(crate) inner: AnyTable,
}

#[pymethods]
impl PyTable {
    /// The spec string: `circle:R=1`, `rectangle:L=1,H=1`, `stadium:a=1`,
    /// `sinai:L=2,R=1` (which `spinball.table` reads back) or
    /// `segments(N walls)`.
    #[getter]
    fn spec(&self) -> String {
        self.inner.spec()
    }
    /// Area of the table.
    #[getter]
    fn area(&self) -> f64 {
        with_table!(&self.inner, |t| t.area())
    }
    /// Length of the boundary.
    #[getter]
    fn perimeter(&self) -> f64 {
        with_table!(&self.inner, |t| t.perimeter())
    }
    /// Length of the curved part of the boundary.
    #[getter]
    fn curved_length(&self) -> f64 {
        with_table!(&self.inner, |t| t.curved_length())
    }
    /// Bounding box `(xmin, ymin, xmax, ymax)`.
    #[getter]
    fn bounds(&self) -> (f64, f64, f64, f64) {
        let b = with_table!(&self.inner, |t| t.aabb());
        (b.min.x, b.min.y, b.max.x, b.max.y)
    }
    /// The table as data (the Rust `Shape` serialised: what a result's
    /// provenance records), as a dict.
    #[getter]
    fn shape<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let shape = with_table!(&self.inner, |t| t.shape());
        let text = serde_json::to_string(&shape)
            .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
        py.import("json")?.call_method1("loads", (text,))
    }
    /// The walls as closed polylines, for drawing: a list of
    /// `(points, is_hole)`, `points` an `(n, 2)` float array whose last row
    /// repeats the first; the outer wall first and counter-clockwise,
    /// obstacles (holes) clockwise; flat walls by their ends, arcs sampled
    /// every half degree.
    fn outline<'py>(&self, py: Python<'py>) -> PyResult<Vec<(Bound<'py, PyArray2<f64>>, bool)>> {
        let outline = with_table!(&self.inner, |t| t.outline());
        outline
            .loops()
            .iter()
            .map(|l| {
                let flat: Vec<f64> = l.points().iter().flat_map(|p| [p.x, p.y]).collect();
                let array = Array2::from_shape_vec((l.points().len(), 2), flat)
                    .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
                Ok((array.into_pyarray(py), l.is_hole()))
            })
            .collect()
    }
    /// Whether the point `(x, y)` lies inside the table.
    fn contains(&self, x: f64, y: f64) -> bool {
        with_table!(&self.inner, |t| t.contains(DVec2::new(x, y)))
    }
    fn __repr__(&self) -> String {
        self.inner.repr()
    }
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyTable>()
            .is_ok_and(|o| o.get().inner == self.inner)
    }
}

/// The keywords of a table class: the names of its spec string
/// (`sinai:L=2,R=1` is `Sinai(L=2, R=1)`), with the lower-case names of
/// spinball 0.2 (`radius`, `l`, `h`, `r`) still read, with a
/// `DeprecationWarning`.
struct Keywords<'py> {
    class: &'static str,
    old: Option<Bound<'py, PyDict>>,
}

impl<'py> Keywords<'py> {
    fn new(class: &'static str, old: Option<&Bound<'py, PyDict>>) -> Self {
        Keywords {
            class,
            old: old.cloned(),
        }
    }

    /// The value of keyword `name` (given as `value`, or as the old name
    /// `old_name`), else `default`.
    fn take(&self, value: Option<f64>, name: &str, old_name: &str, default: f64) -> PyResult<f64> {
        let Some(old) = &self.old else {
            return Ok(value.unwrap_or(default));
        };
        let Some(given) = old.get_item(old_name)? else {
            return Ok(value.unwrap_or(default));
        };
        old.del_item(old_name)?;
        if value.is_some() {
            return Err(PyTypeError::new_err(format!(
                "{}() got {name} and its old name {old_name}: give {name} only",
                self.class
            )));
        }
        let py = old.py();
        PyErr::warn(
            py,
            &py.get_type::<PyDeprecationWarning>(),
            &std::ffi::CString::new(format!(
                "{}({old_name}=...) is deprecated: the keyword is {name}, as in the spec string",
                self.class
            ))
            .unwrap_or_default(),
            1,
        )?;
        given.extract()
    }

    /// Refuse any keyword left over.
    fn finish(self, names: &str) -> PyResult<()> {
        match self.old.as_ref().and_then(|d| d.keys().iter().next()) {
            Some(k) => Err(PyTypeError::new_err(format!(
                "{}() got an unexpected keyword argument {k}: its keywords are {names}, as in the spec string",
                self.class
            ))),
            None => Ok(()),
        }
    }
}

fn base(table: impl Into<Table>) -> PyClassInitializer<PyTable> {
    PyClassInitializer::from(PyTable {
        inner: AnyTable::Builtin(table.into()),
    })
}

/// A circle of radius `R` about the origin (integrable); the spec
/// `circle:R=1`. (`radius=` still works, deprecated.)
///
/// Raises `ValueError` unless `R` is finite and > 0.
#[pyclass(frozen, extends = PyTable, name = "Circle", module = "spinball")]
pub struct PyCircle {
    inner: Circle,
}

#[pymethods]
impl PyCircle {
    #[new]
    #[pyo3(signature = (R = None, **old))]
    #[allow(non_snake_case)]
    fn new(R: Option<f64>, old: Option<&Bound<'_, PyDict>>) -> PyResult<PyClassInitializer<Self>> {
        let k = Keywords::new("Circle", old);
        let radius = k.take(R, "R", "radius", 1.0)?;
        k.finish("R")?;
        let t = Circle::new(radius).map_err(geometry)?;
        Ok(base(t).add_subclass(PyCircle { inner: t }))
    }
    /// Radius.
    #[getter]
    #[allow(non_snake_case)]
    fn R(&self) -> f64 {
        self.inner.radius()
    }
    /// Radius (the old name of `R`).
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
}

/// The rectangle `[-L, L] × [-H, H]` (integrable; `L`, `H` are
/// half-sides); the spec `rectangle:L=1,H=1`. (`l=`, `h=` still work,
/// deprecated.)
///
/// Raises `ValueError` unless both are finite and > 0.
#[pyclass(frozen, extends = PyTable, name = "Rectangle", module = "spinball")]
pub struct PyRectangle {
    inner: Rectangle,
}

#[pymethods]
impl PyRectangle {
    #[new]
    #[pyo3(signature = (L = None, H = None, **old))]
    #[allow(non_snake_case)]
    fn new(
        L: Option<f64>,
        H: Option<f64>,
        old: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let k = Keywords::new("Rectangle", old);
        let l = k.take(L, "L", "l", 1.0)?;
        let h = k.take(H, "H", "h", 1.0)?;
        k.finish("L, H")?;
        let t = Rectangle::new(l, h).map_err(geometry)?;
        Ok(base(t).add_subclass(PyRectangle { inner: t }))
    }
    /// Half-width.
    #[getter]
    #[allow(non_snake_case)]
    fn L(&self) -> f64 {
        self.inner.l()
    }
    /// Half-height.
    #[getter]
    #[allow(non_snake_case)]
    fn H(&self) -> f64 {
        self.inner.h()
    }
    /// Half-width (the old name of `L`).
    #[getter]
    fn l(&self) -> f64 {
        self.inner.l()
    }
    /// Half-height (the old name of `H`).
    #[getter]
    fn h(&self) -> f64 {
        self.inner.h()
    }
}

/// The Bunimovich stadium: flat walls of half-length `a` joined by unit
/// semicircles (chaotic for `a > 0`); the spec `stadium:a=1`.
///
/// Raises `ValueError` unless `a` is finite and > 0.
#[pyclass(frozen, extends = PyTable, name = "Stadium", module = "spinball")]
pub struct PyStadium {
    inner: Stadium,
}

#[pymethods]
impl PyStadium {
    #[new]
    #[pyo3(signature = (a = 1.0))]
    fn new(a: f64) -> PyResult<PyClassInitializer<Self>> {
        let t = Stadium::new(a).map_err(geometry)?;
        Ok(base(t).add_subclass(PyStadium { inner: t }))
    }
    /// Half-length of the flat walls.
    #[getter]
    fn a(&self) -> f64 {
        self.inner.a()
    }
}

/// The Sinai billiard: the square `[-L, L]²` minus the disk of radius `R`
/// about the origin (dispersing); the spec `sinai:L=2,R=1`. (`l=`, `r=`
/// still work, deprecated.)
///
/// Raises `ValueError` unless both are finite, > 0 and `R < L`.
#[pyclass(frozen, extends = PyTable, name = "Sinai", module = "spinball")]
pub struct PySinai {
    inner: Sinai,
}

#[pymethods]
impl PySinai {
    #[new]
    #[pyo3(signature = (L = None, R = None, **old))]
    #[allow(non_snake_case)]
    fn new(
        L: Option<f64>,
        R: Option<f64>,
        old: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let k = Keywords::new("Sinai", old);
        let l = k.take(L, "L", "l", 2.0)?;
        let r = k.take(R, "R", "r", 1.0)?;
        k.finish("L, R")?;
        let t = Sinai::new(l, r).map_err(geometry)?;
        Ok(base(t).add_subclass(PySinai { inner: t }))
    }
    /// Half-side of the square.
    #[getter]
    #[allow(non_snake_case)]
    fn L(&self) -> f64 {
        self.inner.l()
    }
    /// Radius of the obstacle.
    #[getter]
    #[allow(non_snake_case)]
    fn R(&self) -> f64 {
        self.inner.r()
    }
    /// Half-side of the square (the old name of `L`).
    #[getter]
    fn l(&self) -> f64 {
        self.inner.l()
    }
    /// Radius of the obstacle (the old name of `R`).
    #[getter]
    fn r(&self) -> f64 {
        self.inner.r()
    }
}

/// The built-in table a spec string names: `circle`, `circle:R=1`,
/// `rectangle:L=1,H=1`, `stadium:a=1`, `sinai:L=2,R=1` (missing keys take
/// the paper's values); with a hole, `stadium:a=1,hole=0.2` (centred on the
/// right cap, `at=S` moves it), `sinai:L=2,R=1,hole=0.2`,
/// `circle:R=1,hole=0.3` (a `SegmentTable`); a Lorentz gas's cell,
/// `lorentz:lattice=triangular,w=1,R=0.45`. Raises `ValueError` for an
/// unknown table or key, or invalid numbers.
#[pyfunction]
pub fn table(py: Python<'_>, spec: &str) -> PyResult<Py<PyAny>> {
    let t: Built = spec
        .parse()
        .map_err(|e| value_error(format!("table spec `{spec}`: {e}")))?;
    match t {
        Built::Table(t) => builtin_object(py, t),
        Built::Segments(t) => Ok(Py::new(py, segment_table(t))?.into_any()),
    }
}

/// The Python object of a built-in table.
fn builtin_object(py: Python<'_>, t: Table) -> PyResult<Py<PyAny>> {
    Ok(match t {
        Table::Circle(c) => Py::new(py, base(c).add_subclass(PyCircle { inner: c }))?.into_any(),
        Table::Rectangle(r) => {
            Py::new(py, base(r).add_subclass(PyRectangle { inner: r }))?.into_any()
        }
        Table::Stadium(s) => Py::new(py, base(s).add_subclass(PyStadium { inner: s }))?.into_any(),
        Table::Sinai(s) => Py::new(py, base(s).add_subclass(PySinai { inner: s }))?.into_any(),
    })
}

/// The table a table file describes (`.toml` or `.json`: a polygon, loops
/// of `line` and `arc` walls with holes, or a built-in spec; the format is
/// in docs/TABLE_FILES.md, the same files the `spinball` command line
/// reads). Raises `ValueError` for a file that cannot be read or parsed
/// (with the line and column) or walls that do not make a table.
#[pyfunction]
pub fn table_file(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Py<PyAny>> {
    let built = TableFile::load(&path).map_err(|e| value_error(e.to_string()))?;
    match built {
        Built::Table(t) => builtin_object(py, t),
        Built::Segments(t) => Ok(Py::new(py, segment_table(t))?.into_any()),
    }
}

/// A flat wall from `start` to `end` (points `(x, y)`); the table lies on
/// its left. Raises `ValueError` for non-finite or coinciding points.
#[pyclass(frozen, name = "Line", module = "spinball")]
#[derive(Clone)]
pub struct PyLine {
    inner: LineSegment,
}

#[pymethods]
impl PyLine {
    #[new]
    fn new(start: &Bound<'_, PyAny>, end: &Bound<'_, PyAny>) -> PyResult<Self> {
        let (a, b) = (pair(start, "start")?, pair(end, "end")?);
        let inner =
            LineSegment::new(DVec2::new(a.0, a.1), DVec2::new(b.0, b.1)).map_err(geometry)?;
        Ok(PyLine { inner })
    }
    /// First point `(x, y)`.
    #[getter]
    fn start(&self) -> (f64, f64) {
        self.inner.start().into()
    }
    /// Last point `(x, y)`.
    #[getter]
    fn end(&self) -> (f64, f64) {
        self.inner.end().into()
    }
    /// Length.
    #[getter]
    fn length(&self) -> f64 {
        self.inner.length()
    }
    fn __repr__(&self) -> String {
        format!("Line(start={:?}, end={:?})", self.start(), self.end())
    }
}

/// A circular wall: radius `radius` about `center`, from angle
/// `start_angle` (radians from +x) sweeping `sweep` radians. `sweep > 0`
/// runs counter-clockwise and makes a concave wall (the table inside the
/// circle), `sweep < 0` a convex one. Raises `ValueError` for non-finite
/// values, `radius <= 0` or `|sweep|` not in `(0, 2π]`.
#[pyclass(frozen, name = "Arc", module = "spinball")]
#[derive(Clone)]
pub struct PyArc {
    inner: ArcSegment,
}

#[pymethods]
impl PyArc {
    #[new]
    fn new(center: &Bound<'_, PyAny>, radius: f64, start_angle: f64, sweep: f64) -> PyResult<Self> {
        let c = pair(center, "center")?;
        let inner =
            ArcSegment::new(DVec2::new(c.0, c.1), radius, start_angle, sweep).map_err(geometry)?;
        Ok(PyArc { inner })
    }
    /// Centre `(x, y)`.
    #[getter]
    fn center(&self) -> (f64, f64) {
        self.inner.center().into()
    }
    /// Radius.
    #[getter]
    fn radius(&self) -> f64 {
        self.inner.radius()
    }
    /// Start angle (radians).
    #[getter]
    fn start_angle(&self) -> f64 {
        self.inner.start_angle()
    }
    /// Signed sweep (radians; > 0 concave).
    #[getter]
    fn sweep(&self) -> f64 {
        self.inner.sweep()
    }
    /// First point `(x, y)`.
    #[getter]
    fn start(&self) -> (f64, f64) {
        self.inner.start().into()
    }
    /// Last point `(x, y)`.
    #[getter]
    fn end(&self) -> (f64, f64) {
        self.inner.end().into()
    }
    /// Length.
    #[getter]
    fn length(&self) -> f64 {
        self.inner.length()
    }
    fn __repr__(&self) -> String {
        format!(
            "Arc(center={:?}, radius={:?}, start_angle={:?}, sweep={:?})",
            self.center(),
            self.radius(),
            self.start_angle(),
            self.sweep()
        )
    }
}

/// A list of `Line` / `Arc` objects as walls.
fn walls(list: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Segment>> {
    let mut out = Vec::new();
    for (i, w) in list.try_iter()?.enumerate() {
        let w = w?;
        if let Ok(l) = w.cast::<PyLine>() {
            out.push(Segment::Line(l.get().inner));
        } else if let Ok(a) = w.cast::<PyArc>() {
            out.push(Segment::Arc(a.get().inner));
        } else {
            return Err(PyTypeError::new_err(format!(
                "{what}[{i}]: expected a spinball.Line or spinball.Arc, got {}",
                w.get_type().name()?
            )));
        }
    }
    Ok(out)
}

fn segment_object(py: Python<'_>, s: &Segment) -> PyResult<Py<PyAny>> {
    Ok(match *s {
        Segment::Line(inner) => Py::new(py, PyLine { inner })?.into_any(),
        Segment::Arc(inner) => Py::new(py, PyArc { inner })?.into_any(),
    })
}

pub(crate) fn segment_table(t: SegmentTable) -> PyClassInitializer<PySegmentTable> {
    PyClassInitializer::from(PyTable {
        inner: AnyTable::Segments(t.clone()),
    })
    .add_subclass(PySegmentTable { inner: t })
}

/// A table bounded by your own walls: `outer`, a counter-clockwise closed
/// loop of `Line` and `Arc` walls (the table on the left of each), and
/// `holes`, each a clockwise closed loop. Runs in the same vector lanes as
/// the built-in tables. Raises `ValueError` for an empty loop, a gap
/// between consecutive walls, or a loop with the wrong orientation;
/// `TypeError` for something that is not a wall.
#[pyclass(frozen, extends = PyTable, name = "SegmentTable", module = "spinball")]
pub struct PySegmentTable {
    inner: SegmentTable,
}

#[pymethods]
impl PySegmentTable {
    #[new]
    #[pyo3(signature = (outer, holes = None))]
    fn new(
        outer: &Bound<'_, PyAny>,
        holes: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let outer = walls(outer, "outer")?;
        let holes = match holes {
            None => Vec::new(),
            Some(h) => h
                .try_iter()?
                .enumerate()
                .map(|(i, hole)| walls(&hole?, &format!("holes[{i}]")))
                .collect::<PyResult<_>>()?,
        };
        let t = SegmentTable::with_holes(outer, holes).map_err(geometry)?;
        Ok(segment_table(t))
    }
    /// The polygon through `vertices` (an `(n, 2)` array or a list of
    /// `(x, y)`, counter-clockwise; the closing wall is added). Raises
    /// `ValueError` for fewer than 3 vertices, repeated vertices or a
    /// clockwise order.
    #[staticmethod]
    fn polygon(py: Python<'_>, vertices: &Bound<'_, PyAny>) -> PyResult<Py<PySegmentTable>> {
        let v: Vec<DVec2> = rows(vertices, 2, "vertices")?
            .into_iter()
            .map(|r| DVec2::new(r[0], r[1]))
            .collect();
        let t = SegmentTable::polygon(&v).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The same table with wall `wall` (its index: outer walls first, then
    /// the holes' in order) made a hole: a ball reaching it leaves. Raises
    /// `ValueError` for a wall that does not exist or is already a hole or
    /// periodic.
    fn with_hole(&self, py: Python<'_>, wall: u32) -> PyResult<Py<PySegmentTable>> {
        let t = self.inner.clone().with_hole(wall).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The same table with walls `a` and `b` periodic partners (two
    /// parallel straight walls of equal length, translates of each other):
    /// a ball leaving through one re-enters through the other, one cell
    /// further on. Raises `ValueError` otherwise.
    fn with_periodic(&self, py: Python<'_>, a: u32, b: u32) -> PyResult<Py<PySegmentTable>> {
        let t = self.inner.clone().with_periodic(a, b).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The same table with a hole of arc length `size` centred at Birkhoff
    /// coordinate `s` (the stretch must lie within one wall, which is split
    /// there). Raises `ValueError` otherwise.
    fn with_hole_at(&self, py: Python<'_>, s: f64, size: f64) -> PyResult<Py<PySegmentTable>> {
        let t = self.inner.with_hole_at(s, size).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The stadium of flat half-length `a` with a hole of arc length `size`
    /// centred at Birkhoff `s` (the `Stadium`'s parametrisation; the right
    /// cap's middle is `s = 2a + π/2`).
    #[staticmethod]
    fn stadium_with_hole(
        py: Python<'_>,
        a: f64,
        s: f64,
        size: f64,
    ) -> PyResult<Py<PySegmentTable>> {
        let t = SegmentTable::stadium_with_hole(a, s, size).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The Sinai table (`L`, `R`) with a hole of arc length `size` centred
    /// at Birkhoff `s`.
    #[staticmethod]
    #[allow(non_snake_case)]
    fn sinai_with_hole(
        py: Python<'_>,
        L: f64,
        R: f64,
        s: f64,
        size: f64,
    ) -> PyResult<Py<PySegmentTable>> {
        let t = SegmentTable::sinai_with_hole(L, R, s, size).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// The circle of radius `R` with a hole of arc length `size` centred at
    /// polar angle `angle`.
    #[staticmethod]
    #[allow(non_snake_case)]
    fn circle_with_hole(
        py: Python<'_>,
        R: f64,
        angle: f64,
        size: f64,
    ) -> PyResult<Py<PySegmentTable>> {
        let t = SegmentTable::circle_with_hole(R, angle, size).map_err(geometry)?;
        Py::new(py, segment_table(t))
    }
    /// What each wall does, in wall order: `"reflecting"`, `"hole"` or
    /// `"periodic"`.
    #[getter]
    fn kinds(&self) -> Vec<&'static str> {
        self.inner
            .kinds()
            .iter()
            .map(|k| {
                if k.is_hole() {
                    "hole"
                } else if k.is_periodic() {
                    "periodic"
                } else {
                    "reflecting"
                }
            })
            .collect()
    }
    /// The outer walls, as `Line` / `Arc` objects.
    #[getter]
    fn outer<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let items = self
            .inner
            .outer()
            .iter()
            .map(|s| segment_object(py, s))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }
    /// The holes, each a list of `Line` / `Arc` objects.
    #[getter]
    fn holes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let holes = self
            .inner
            .holes()
            .into_iter()
            .map(|h| {
                let items = h
                    .iter()
                    .map(|s| segment_object(py, s))
                    .collect::<PyResult<Vec<_>>>()?;
                PyList::new(py, items)
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, holes)
    }
}
