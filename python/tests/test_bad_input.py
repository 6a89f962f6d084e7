"""The issue's bad input, fed to every call that takes it (ctest `python_module`): wrong NumPy
dtypes and shapes (a 2-D array where 3-D is expected, integers, non-contiguous views), NaN and inf,
a rig and binding that do not match, a path that does not exist. Each is a Python exception with a
clear message or, where the input has one meaning (integer weights, strided views), the same result
as the plain float64 array; never a crash, and nothing written on failure."""

import os
import pathlib

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
RIG = SAMPLE_DIR / "ict_face_rig.glb"
RIG_BINDING = SAMPLE_DIR / "Facial-Sing.ict_face_rig.binding.json"
FACE = SAMPLE_DIR / "canonical_face_model.obj"
FACE_BINDING = SAMPLE_DIR / "Facial-Sing.binding.json"


@pytest.fixture(scope="module")
def rig():
    return mocap.load_rig(RIG)


@pytest.fixture(scope="module")
def weights(rig):
    """Ten frames of weights, every shape at a different value."""
    return np.linspace(0.0, 1.0, 10 * rig.shape_count).reshape(10, rig.shape_count)


def weight_writers(rig):
    """Every call taking frames × shapes weights, writing to `path`."""
    return {
        "write_weights_csv": lambda path, w: mocap.write_weights_csv(path, rig.names, w, 100.0),
        "write_live_link_csv": lambda path, w: mocap.write_live_link_csv(path, rig.names, w, 100.0),
        "write_rig_glb": lambda path, w: mocap.write_rig_glb(path, rig, w, 100.0),
        "write_rig_fbx": lambda path, w: mocap.write_rig_fbx(path, rig, w, 100.0),
        "write_pc2": lambda path, w: mocap.write_pc2(path, rig, w),
    }


SUFFIX = {"write_rig_glb": ".glb", "write_rig_fbx": ".fbx", "write_pc2": ".pc2"}


@pytest.mark.parametrize("writer", ["write_weights_csv", "write_live_link_csv", "write_rig_glb", "write_rig_fbx",
                                    "write_pc2"])
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_nan_and_inf_weights_raise_and_write_nothing(tmp_path, rig, weights, writer, bad):
    out = tmp_path / ("out" + SUFFIX.get(writer, ".csv"))
    w = weights.copy()
    w[4, 7] = bad
    with pytest.raises(mocap.InvalidArgument, match="not finite"):
        weight_writers(rig)[writer](out, w)
    assert list(tmp_path.iterdir()) == [], "nothing written"


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_nan_and_inf_weights_raise_where_nothing_is_written(rig, weights, bad):
    w = weights.copy()
    w[2, 3] = bad
    with pytest.raises(mocap.InvalidArgument, match=r"weights\[2, 3\] is not finite"):
        mocap.retarget_weights(rig.names, w, "ict_to_arkit")
    with pytest.raises(mocap.InvalidArgument, match="not finite"):
        rig.evaluate(w[2])


@pytest.mark.parametrize("writer", ["write_weights_csv", "write_rig_glb", "write_rig_fbx", "write_pc2"])
def test_weights_of_the_wrong_shape_raise_and_write_nothing(tmp_path, rig, weights, writer):
    out = tmp_path / ("out" + SUFFIX.get(writer, ".csv"))
    with pytest.raises(mocap.InvalidArgument):  # a column short: 52 weights for 53 shapes
        weight_writers(rig)[writer](out, weights[:, 1:])
    with pytest.raises(TypeError):  # 3-D where frames × shapes is expected
        weight_writers(rig)[writer](out, weights.reshape(10, rig.shape_count, 1).repeat(2, axis=2))
    with pytest.raises(TypeError):  # not numbers at all
        weight_writers(rig)[writer](out, np.array([["a"] * rig.shape_count]))
    assert list(tmp_path.iterdir()) == [], "nothing written"


@pytest.mark.parametrize("writer", ["write_weights_csv", "write_live_link_csv", "write_rig_glb", "write_rig_fbx",
                                    "write_pc2"])
def test_integer_weights_and_strided_views_write_what_float64_writes(tmp_path, rig, weights, writer):
    write = weight_writers(rig)[writer]
    suffix = SUFFIX.get(writer, ".csv")
    binary = np.zeros_like(weights)
    binary[::3, ::2] = 1.0
    write(tmp_path / ("float" + suffix), binary)
    write(tmp_path / ("int" + suffix), binary.astype(np.int32))
    assert (tmp_path / ("int" + suffix)).read_bytes() == (tmp_path / ("float" + suffix)).read_bytes()
    wide = np.zeros((weights.shape[0], 2 * weights.shape[1]))
    wide[:, ::2] = weights
    view = wide[:, ::2]
    assert not view.flags["C_CONTIGUOUS"] and not view.flags["F_CONTIGUOUS"]
    write(tmp_path / ("view" + suffix), view)
    write(tmp_path / ("plain" + suffix), np.ascontiguousarray(view))
    assert (tmp_path / ("view" + suffix)).read_bytes() == (tmp_path / ("plain" + suffix)).read_bytes()


def test_positions_need_a_float64_frames_markers_3_array_and_change_nothing_otherwise():
    take = mocap.read(TAKE)
    before = take.raw_positions.copy()
    shape = (take.frame_count, take.marker_count, 3)
    with pytest.raises(ValueError, match=r"\(3000, %d, 3\)" % take.marker_count):  # 2-D where 3-D is expected
        take.positions = np.zeros((take.frame_count, take.marker_count * 3))
    with pytest.raises(TypeError, match="float64"):
        take.positions = np.zeros(shape, dtype=np.int64)
    with pytest.raises(TypeError, match="float64"):
        take.positions = np.zeros(shape, dtype=np.float32)
    infinite = take.positions
    infinite[10, 2, 1] = np.inf
    with pytest.raises(ValueError, match=r"positions\[10, 2, 1\] is infinite"):
        take.positions = infinite
    assert np.array_equal(take.raw_positions, before), "a refused array changes no sample"
    strided = np.zeros((shape[0], shape[1], 6))[:, :, ::2]
    strided[:] = np.nan_to_num(take.positions)
    take.positions = strided  # a non-contiguous view is read through its strides
    assert take.valid.all() and np.array_equal(take.positions, strided)


def test_a_rig_and_binding_that_do_not_match_raise(rig, tmp_path):
    take = mocap.read(TAKE)
    face_binding = mocap.read_binding(FACE_BINDING, FACE)
    with pytest.raises(mocap.InvalidArgument, match="468"):
        mocap.solve(take, rig, face_binding)
    with pytest.raises(mocap.Error):
        mocap.read_binding(FACE_BINDING, rig)
    with pytest.raises(mocap.Error):
        mocap.deform(take, rig, face_binding, frames=(1, 2))
    with pytest.raises(mocap.InvalidArgument, match="468 vertices"):
        mocap.plan_layout(take, rig=rig, binding=face_binding)
    other = mocap.load_rig(RIG, only=rig.names[:5])
    with pytest.raises(mocap.InvalidArgument):  # weights of the full rig on a 5-shape rig
        mocap.write_rig_glb(tmp_path / "x.glb", other, np.zeros((3, rig.shape_count)), 100.0)
    assert list(tmp_path.iterdir()) == []


def test_paths_that_do_not_exist_raise_io_errors_naming_them(rig, tmp_path):
    missing = tmp_path / "missing"
    take = mocap.read(TAKE)
    calls = {
        "read": lambda: mocap.read(missing / "take.c3d"),
        "load_rig": lambda: mocap.load_rig(missing / "rig.glb"),
        "read_binding": lambda: mocap.read_binding(missing / "b.json", rig),
        "bind": lambda: mocap.bind(take, missing / "face.obj"),
        "deform": lambda: mocap.deform(take, missing / "face.obj", mocap.read_binding(FACE_BINDING, FACE)),
        "clean": lambda: mocap.clean(take, missing / "preset.json"),
        "plan_layout": lambda: mocap.plan_layout(take, pairs=missing / "pairs.json"),
        "write_weights_csv map": lambda: mocap.write_weights_csv(tmp_path / "w.csv", rig.names,
                                                                 np.zeros((2, rig.shape_count)), 100.0,
                                                                 map=missing / "map.json"),
    }
    for name, call in calls.items():
        with pytest.raises(mocap.IoError, match="missing"):
            call()
    zeros = np.zeros((2, rig.shape_count))
    for name, write in (("out.c3d", take.write), ("out.fbx", lambda p: mocap.write_markers_fbx(p, take)),
                        ("out.glb", lambda p: mocap.write_rig_glb(p, rig, zeros, 100.0)),
                        ("out.pc2", lambda p: mocap.write_pc2(p, rig, zeros)),
                        ("out.csv", lambda p: mocap.write_weights_csv(p, rig.names, zeros, 100.0))):
        with pytest.raises(mocap.IoError, match="missing"):
            write(missing / name)
    assert list(tmp_path.iterdir()) == [], "nothing written"
