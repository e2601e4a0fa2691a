//! Arrays in and out: an argument's shape is checked and named before any
//! number reaches the library (which checks the numbers), and results are
//! float64 NumPy arrays (the library's f32 values, exactly).

use crate::ShapeError;
use coulomb_hands::hand::{Bone, Capsule, Finger, HandPose, Palm, Phalanx};
use glam::{Quat, Vec3};
use numpy::{
    PyArray1, PyArray2, PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `contacts()["state"]`'s codes, by index.
pub const FRICTION_STATES: [&str; 3] = coulomb_hands::FrictionState::NAMES;
/// `events()["kind"]`'s codes, by index.
pub const EVENT_KINDS: [&str; 2] = coulomb_hands::ContactEventKind::NAMES;

/// The 16 bones' names, by `Bone::index`: `palm`, then `thumb proximal` …
/// `little distal`.
pub fn bone_names() -> Vec<String> {
    Bone::all()
        .map(|b| match b {
            Bone::Palm => "palm".to_string(),
            Bone::Finger(f, p) => format!("{} {}", finger_name(f), phalanx_name(p)),
        })
        .collect()
}

fn finger_name(f: Finger) -> &'static str {
    ["thumb", "index", "middle", "ring", "little"][f as usize]
}

fn phalanx_name(p: Phalanx) -> &'static str {
    ["proximal", "intermediate", "distal"][p as usize]
}

/// `value` as a float64 array: as it is if it is one, else converted by
/// `numpy.asarray` (lists, float32 arrays). Not numbers: a `ShapeError`
/// naming `what`.
fn float_array<'py>(
    value: &Bound<'py, PyAny>,
    what: &str,
) -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
    if let Ok(a) = value.cast::<PyArrayDyn<f64>>() {
        return Ok(a.readonly());
    }
    let numpy = value.py().import("numpy")?;
    let converted = numpy
        .call_method1("asarray", (value, "float64"))
        .map_err(|e| ShapeError::new_err(format!("{what}: expected an array of numbers ({e})")))?;
    Ok(converted.cast_into::<PyArrayDyn<f64>>()?.readonly())
}

/// The shape as NumPy prints it, e.g. `(21, 3)`.
fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")),
    }
}

/// The rows of an `(n, columns)` array, `n` being `rows` if given, each as
/// f32 (as the library's loaders take JSON's f64 numbers).
pub fn rows<const C: usize>(
    value: &Bound<'_, PyAny>,
    what: &str,
    rows: Option<usize>,
) -> PyResult<Vec<[f32; C]>> {
    let array = float_array(value, what)?;
    let shape = array.shape();
    let fits = shape.len() == 2 && shape[1] == C && rows.is_none_or(|n| shape[0] == n);
    if !fits {
        let n = rows.map_or("n".to_string(), |n| n.to_string());
        let got = shape_text(shape);
        return Err(ShapeError::new_err(format!("{what}: expected shape ({n}, {C}), got {got}")));
    }
    let view = array.as_array();
    let mut out = Vec::with_capacity(shape[0]);
    for row in view.outer_iter() {
        out.push(std::array::from_fn(|i| row[i] as f32));
    }
    Ok(out)
}

/// The numbers of a `(n,)` array, `n` being `len` if given, as f32.
pub fn column(value: &Bound<'_, PyAny>, what: &str, len: Option<usize>) -> PyResult<Vec<f32>> {
    let array = float_array(value, what)?;
    let shape = array.shape();
    if shape.len() != 1 || len.is_some_and(|n| shape[0] != n) {
        let n = len.map_or("n".to_string(), |n| n.to_string());
        let got = shape_text(shape);
        return Err(ShapeError::new_err(format!("{what}: expected shape ({n},), got {got}")));
    }
    Ok(array.as_array().iter().map(|&x| x as f32).collect())
}

/// A point or vector: 3 numbers.
pub fn vec3(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec3> {
    Ok(Vec3::from_array(column(value, what, Some(3))?.try_into().unwrap_or_default()))
}

/// A rotation: 4 numbers, x, y, z, w, made a unit quaternion as every
/// binding makes one (`layouts::rotation`); a zero-length or non-finite
/// one is a `ShapeError` naming the argument.
pub fn quat(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Quat> {
    let q: [f32; 4] = column(value, what, Some(4))?.try_into().unwrap_or_default();
    coulomb_hands::input::layouts::rotation(q)
        .ok_or_else(|| ShapeError::new_err(format!("{what}: zero-length or non-finite rotation")))
}

/// An `(n, C)` float64 array of `rows`.
fn rows_array<'py, const C: usize>(
    py: Python<'py>,
    rows: impl Iterator<Item = [f32; C]>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = rows.flat_map(|r| r.map(f64::from)).collect();
    let n = flat.len() / C;
    PyArray1::from_vec(py, flat).reshape([n, C])
}

/// An `(n, 3)` float64 array of `points`.
pub fn points_array<'py>(
    py: Python<'py>,
    points: impl Iterator<Item = Vec3>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    rows_array(py, points.map(|p| p.to_array()))
}

/// An `(n, 4)` float64 array of quaternions, x, y, z, w.
pub fn quats_array<'py>(
    py: Python<'py>,
    quats: impl Iterator<Item = Quat>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    rows_array(py, quats.map(|q| q.to_array()))
}

/// A `(n,)` array of `values`.
pub fn values_array<T: numpy::Element>(
    py: Python<'_>,
    values: impl Iterator<Item = T>,
) -> Bound<'_, PyArray1<T>> {
    PyArray1::from_vec(py, values.collect())
}

/// A hand pose as a dict of arrays: `palm_center` (3,), `palm_rotation`
/// (4,) x, y, z, w, `palm_half_extents` (3,), and the 15 finger bones'
/// capsules, thumb first, proximal first: `capsule_a` and `capsule_b`
/// (15, 3) and `capsule_radius` (15,).
pub fn pose_dict<'py>(py: Python<'py>, pose: &HandPose) -> PyResult<Bound<'py, PyDict>> {
    let capsules: Vec<&Capsule> = pose.fingers.iter().flatten().collect();
    let dict = PyDict::new(py);
    let p = &pose.palm;
    dict.set_item("palm_center", values_array(py, p.center.to_array().map(f64::from).into_iter()))?;
    let rotation = p.rotation.to_array().map(f64::from);
    dict.set_item("palm_rotation", values_array(py, rotation.into_iter()))?;
    let half = p.half_extents.to_array().map(f64::from);
    dict.set_item("palm_half_extents", values_array(py, half.into_iter()))?;
    dict.set_item("capsule_a", points_array(py, capsules.iter().map(|c| c.a))?)?;
    dict.set_item("capsule_b", points_array(py, capsules.iter().map(|c| c.b))?)?;
    let radii = capsules.iter().map(|c| f64::from(c.radius));
    dict.set_item("capsule_radius", values_array(py, radii))?;
    Ok(dict)
}

/// The pose a dict of [`pose_dict`]'s arrays describes (shapes checked
/// here, numbers by the library when it is set).
pub fn pose_from_dict(dict: &Bound<'_, PyAny>) -> PyResult<HandPose> {
    let item = |key: &str| -> PyResult<Bound<'_, PyAny>> {
        dict.get_item(key).map_err(|_| ShapeError::new_err(format!("pose: missing \"{key}\"")))
    };
    let palm = Palm {
        center: vec3(&item("palm_center")?, "pose[\"palm_center\"]")?,
        rotation: quat(&item("palm_rotation")?, "pose[\"palm_rotation\"]")?,
        half_extents: vec3(&item("palm_half_extents")?, "pose[\"palm_half_extents\"]")?,
    };
    let a = rows::<3>(&item("capsule_a")?, "pose[\"capsule_a\"]", Some(15))?;
    let b = rows::<3>(&item("capsule_b")?, "pose[\"capsule_b\"]", Some(15))?;
    let r = column(&item("capsule_radius")?, "pose[\"capsule_radius\"]", Some(15))?;
    let capsule =
        |i: usize| Capsule { a: Vec3::from_array(a[i]), b: Vec3::from_array(b[i]), radius: r[i] };
    let fingers = std::array::from_fn(|f| std::array::from_fn(|p| capsule(3 * f + p)));
    Ok(HandPose { palm, fingers })
}
