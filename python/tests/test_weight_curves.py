"""Weight curves from Python: the weights CSV and Live Link Face CSV `mocap solve` writes, through a
retarget map or not, and a map applied on its own (ctest `python_module`)."""

import csv
import os
import pathlib
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
RIG = SAMPLE_DIR / "ict_face_rig.glb"
BINDING = SAMPLE_DIR / "Facial-Sing.ict_face_rig.binding.json"


def solve_cli(out, *extra):
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    subprocess.run([cli, "solve", "--mesh", RIG, "--binding", BINDING, "--take", TAKE, "--leave-out", "0",
                    "-o", out, *map(str, extra)], check=True, capture_output=True)


@pytest.fixture(scope="module")
def solved():
    take = mocap.read(TAKE)
    rig = mocap.load_rig(RIG)
    result = mocap.solve(take, rig, mocap.read_binding(BINDING, rig))
    return take, result["names"], result["weights"]


def test_weight_files_are_byte_identical_to_mocap_solves(solved, tmp_path):
    take, names, weights = solved
    for name, write, extra in (
            ("w.csv", lambda p: mocap.write_weights_csv(p, names, weights, take.rate, take.first_frame), ()),
            ("mapped.csv", lambda p: mocap.write_weights_csv(p, names, weights, take.rate, take.first_frame,
                                                             map="ict_to_arkit"), ("--map", "ict_to_arkit")),
            ("ll.csv", lambda p: mocap.write_live_link_csv(p, names, weights, take.rate), ("--format", "livelink")),
            ("ll_identity.csv", lambda p: mocap.write_live_link_csv(p, names, weights, take.rate,
                                                                    map=SOURCE / "resources" / "retarget" /
                                                                    "ict_to_arkit.json"),
             ("--format", "livelink", "--map", SOURCE / "resources" / "retarget" / "ict_to_arkit.json"))):
        ours, theirs = tmp_path / ("py_" + name), tmp_path / ("cli_" + name)
        write(ours)
        solve_cli(theirs, *extra)
        assert ours.read_bytes() == theirs.read_bytes(), name


def test_retarget_weights_gives_the_mapped_columns_of_the_written_file(solved, tmp_path):
    take, names, weights = solved
    channels, mapped = mocap.retarget_weights(names, weights, "ict_to_arkit")
    assert mapped.shape == (take.frame_count, len(channels)) and "JawOpen" in channels
    mocap.write_weights_csv(tmp_path / "m.csv", names, weights, take.rate, map="ict_to_arkit")
    with open(tmp_path / "m.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][2:] == list(channels)
    np.testing.assert_allclose(np.array(rows[1:], dtype=float)[:, 2:], mapped, rtol=0, atol=1e-12)


def test_bad_weights_are_clear_errors_and_write_nothing(solved, tmp_path):
    take, names, weights = solved
    out = tmp_path / "x.csv"
    bad = weights.copy()
    bad[3, 2] = np.nan
    with pytest.raises(mocap.InvalidArgument, match=r"weights\[3, 2\] is not finite"):
        mocap.write_weights_csv(out, names, bad, take.rate)
    with pytest.raises(mocap.InvalidArgument, match="not finite"):
        mocap.write_live_link_csv(out, names, bad, take.rate)
    with pytest.raises(mocap.InvalidArgument, match="names"):
        mocap.write_weights_csv(out, names[:-1], weights, take.rate)
    with pytest.raises(mocap.InvalidArgument, match="head_rotation"):
        mocap.write_live_link_csv(out, names, weights, take.rate, head_rotation=np.zeros((2, 3)))
    with pytest.raises(mocap.IoError):
        mocap.write_weights_csv(out, names, weights, take.rate, map="no_such_map")
    with pytest.raises(mocap.InvalidArgument):
        mocap.write_live_link_csv(out, ["notAShape"], weights[:, :1], take.rate)
    with pytest.raises(mocap.InvalidArgument, match="map"):
        mocap.retarget_weights(names, weights, None)
    with pytest.raises(TypeError):
        mocap.write_weights_csv(out, names, "weights", take.rate)
    assert not out.exists()
