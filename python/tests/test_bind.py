"""mocap.bind: markers bound to a face mesh as `mocap bind` binds them (ctest `python_module`)."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
FACE = SAMPLE_DIR / "canonical_face_model.obj"
HEAD = ["root-%d" % i for i in range(1, 7)]


def bind_cli(out, *extra):
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    subprocess.run([cli, "bind", "--mesh", FACE, "--take", TAKE, "-o", out, *map(str, extra)],
                   check=True, capture_output=True)
    return out.read_text()


def test_bind_writes_what_mocap_bind_writes_and_leaves_the_take(tmp_path):
    take = mocap.read(TAKE)
    before = take.raw_positions.copy()
    faces = [label for label in take.labels if label.startswith("section")]
    binding = mocap.bind(take, FACE, stabilize=HEAD, markers=faces)
    assert binding.json() == bind_cli(tmp_path / "cli.json", "--stabilize", ",".join(HEAD), "--markers", ",".join(faces))
    assert binding.labels == faces and len(binding.residuals) == len(faces)
    assert 0 < np.mean(binding.residuals) < 10
    assert np.array_equal(take.raw_positions, before)
    binding.write(tmp_path / "py.json")
    assert (tmp_path / "py.json").read_text() == binding.json()


def test_bind_on_pairs_and_a_frame_as_mocap_bind_does(tmp_path):
    take = mocap.read(TAKE)
    faces = ["section1-1", "section5-1", "section10-1", "section14-1"]
    pairs = {"section1-1": 10, "section5-1": 200, "section10-1": 300}
    binding = mocap.bind(take, FACE, markers=faces, neutral_frame=20, pairs=pairs)
    assert binding.json() == bind_cli(tmp_path / "cli.json", "--markers", ",".join(faces), "--neutral", 20,
                                      "--pairs", ",".join("%s=%d" % p for p in pairs.items()))


def test_bad_bind_arguments_are_clear_errors():
    take = mocap.read(TAKE)
    with pytest.raises(mocap.IoError):
        mocap.bind(take, "/nonexistent/face.obj")
    with pytest.raises(mocap.InvalidArgument, match="nosuch"):
        mocap.bind(take, FACE, markers=["nosuch", "section1-1", "section1-2"])
    with pytest.raises(mocap.InvalidArgument, match="pairs: root-1"):
        mocap.bind(take, FACE, markers=["section1-1", "section1-2", "section2-1"], pairs={"root-1": 3})
    with pytest.raises(mocap.InvalidArgument, match="vertex 100000"):
        mocap.bind(take, FACE, markers=["section1-1", "section1-2", "section2-1"], pairs={"section1-1": 100000})
    with pytest.raises(mocap.InvalidArgument, match="vertices"):
        mocap.bind(take, FACE, vertices=(10, 5))
    with pytest.raises(mocap.InvalidArgument):
        mocap.bind(take, FACE, neutral_frame=10**6)
    with pytest.raises(TypeError):
        mocap.bind(take, FACE, pairs=[1, 2, 3])
