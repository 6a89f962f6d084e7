"""mocap.deform: the face mesh driven by a take as `mocap deform` drives it (ctest `python_module`)."""

import os
import pathlib
import struct
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
FACE = SAMPLE_DIR / "canonical_face_model.obj"
BINDING = SAMPLE_DIR / "Facial-Sing.binding.json"
HEAD = ["root-%d" % i for i in range(1, 7)]


def read_pc2(path):
    data = path.read_bytes()
    points, _, _, samples = struct.unpack("<iffi", data[16:32])
    return np.frombuffer(data[32:], dtype="<f4").reshape(samples, points, 3)


def deform_cli(tmp_path, *args):
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    out = tmp_path / "cli.pc2"
    subprocess.run([cli, "deform", "--mesh", FACE, "--binding", BINDING, "--take", TAKE, "--leave-out", "0",
                    "-o", out, *map(str, args)], check=True, capture_output=True)
    return read_pc2(out)


@pytest.fixture(scope="module")
def take():
    return mocap.read(TAKE)


@pytest.mark.parametrize("options, cli_args", [
    ({}, ()),
    ({"method": "laplacian", "weights": "cotangent"}, ("--method", "laplacian", "--weights", "cotangent")),
    ({"kernel": "gaussian", "radius": 8.0, "affine": False}, ("--kernel", "gaussian", "--radius", 8, "--no-affine")),
])
def test_deform_gives_the_meshes_of_mocap_deform(tmp_path, take, options, cli_args):
    first = take.first_frame
    theirs = deform_cli(tmp_path, "--stabilize", ",".join(HEAD), "--frames", "%d:%d" % (first + 100, first + 139),
                        *cli_args)
    before = take.raw_positions.copy()
    result = mocap.deform(take, FACE, mocap.read_binding(BINDING, FACE), stabilize=HEAD,
                          frames=(first + 100, first + 139), **options)
    ours = result["vertices"]
    assert ours.shape == theirs.shape == (40, 468, 3)
    np.testing.assert_allclose(ours, theirs, rtol=2e-6, atol=1e-5)
    assert np.array_equal(take.raw_positions, before)
    assert result["method"] == options.get("method", "rbf")


def test_bad_deform_arguments_are_clear_errors(take):
    binding = mocap.read_binding(BINDING, FACE)
    with pytest.raises(mocap.InvalidArgument, match="method"):
        mocap.deform(take, FACE, binding, method="magic")
    with pytest.raises(mocap.InvalidArgument, match="radius"):
        mocap.deform(take, FACE, binding, radius=float("nan"))
    with pytest.raises(mocap.InvalidArgument, match="rotations"):
        mocap.deform(take, FACE, binding, rotations=2)
    with pytest.raises(mocap.InvalidArgument, match="frames"):
        mocap.deform(take, FACE, binding, frames=(0, 10**7))
    with pytest.raises(mocap.IoError):
        mocap.deform(take, "/nonexistent/face.obj", binding)
    rig = mocap.load_rig(SAMPLE_DIR / "ict_face_rig.glb")
    with pytest.raises(mocap.Error):  # a binding made for another mesh
        mocap.deform(take, rig, binding, frames=(1, 2))
