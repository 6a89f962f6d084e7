"""The animation writers from Python write what the command line writes (ctest `python_module`)."""

import os
import pathlib
import subprocess

import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
RIG = SAMPLE_DIR / "ict_face_rig.glb"
BINDING = SAMPLE_DIR / "Facial-Sing.ict_face_rig.binding.json"


def cli(*args):
    path = os.environ.get("MOCAP_CLI")
    if not path:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    subprocess.run([path, *map(str, args)], check=True, capture_output=True)


@pytest.fixture(scope="module")
def solved():
    take = mocap.read(TAKE)
    rig = mocap.load_rig(RIG)
    weights = mocap.solve(take, rig, mocap.read_binding(BINDING, rig))["weights"]
    return take, rig, weights


def solve_cli(out, *extra):
    cli("solve", "--mesh", RIG, "--binding", BINDING, "--take", TAKE, "--leave-out", "0", "-o", out, *extra)


def test_rig_files_are_byte_identical_to_mocap_solves(solved, tmp_path):
    take, rig, weights = solved
    for name, write, extra in (
            ("r.glb", lambda p: mocap.write_rig_glb(p, rig, weights, take.rate), ()),
            ("reduced.glb", lambda p: mocap.write_rig_glb(p, rig, weights, take.rate, reduce=0.01), ("--reduce", 0.01)),
            ("r.fbx", lambda p: mocap.write_rig_fbx(p, rig, weights, take.rate), ()),
            ("reduced.fbx", lambda p: mocap.write_rig_fbx(p, rig, weights, take.rate, reduce=0.01), ("--reduce", 0.01)),
            ("m.pc2", lambda p: mocap.write_pc2(p, rig, weights, take.first_frame), ())):
        ours, theirs = tmp_path / ("py_" + name), tmp_path / ("cli_" + name)
        report = write(ours)
        solve_cli(theirs, *extra)
        assert ours.read_bytes() == theirs.read_bytes(), name
        if extra:
            assert report["keys_after"] < report["keys_before"] and report["max_error"] <= 0.01
        else:
            assert report is None


def test_markers_fbx_is_byte_identical_to_mocap_convert(solved, tmp_path):
    take = solved[0]
    report = mocap.write_markers_fbx(tmp_path / "py.fbx", take, reduce=0.1)
    cli("convert", TAKE, tmp_path / "cli.fbx", "--reduce", 0.1)
    assert (tmp_path / "py.fbx").read_bytes() == (tmp_path / "cli.fbx").read_bytes()
    assert report["keys_after"] < report["keys_before"] and report["max_error"] <= 0.1


def test_bad_arguments_are_clear_errors(solved, tmp_path):
    take, rig, weights = solved
    with pytest.raises(mocap.InvalidArgument, match="up must be"):
        mocap.write_rig_fbx(tmp_path / "x.fbx", rig, weights, take.rate, up="x")
    with pytest.raises(mocap.InvalidArgument, match="units"):
        mocap.write_rig_fbx(tmp_path / "x.fbx", rig, weights, take.rate, units="m")
    with pytest.raises(mocap.InvalidArgument):
        mocap.write_rig_glb(tmp_path / "x.glb", rig, weights[:, :3], take.rate)
    assert not (tmp_path / "x.glb").exists() and not (tmp_path / "x.fbx").exists()
