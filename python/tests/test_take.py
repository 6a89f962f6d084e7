"""The `mocap` module's takes: reading, writing, NumPy arrays and errors (ctest `python_module`)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE = SOURCE / "resources" / "sample" / "Facial-Sing.c3d"
SMALL = SOURCE / "tests" / "data" / "c3d" / "sample02" / "pc_real.c3d"


def cli():
    path = os.environ.get("MOCAP_CLI")
    if not path:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    return path


def test_reads_the_sample_with_nan_in_gaps():
    take = mocap.read(SAMPLE)
    assert take.marker_count == len(take.labels) > 30
    assert take.frame_count == 3000
    assert take.rate == 100.0
    assert take.units == "mm"
    positions = take.positions
    assert positions.shape == (take.frame_count, take.marker_count, 3)
    assert positions.dtype == np.float64
    valid = take.valid
    assert valid.shape == (take.frame_count, take.marker_count)
    assert not valid.all(), "the sample has gaps"
    assert np.isnan(positions[~valid]).all()
    assert np.isfinite(positions[valid]).all()
    assert np.array_equal(take.raw_positions[valid], positions[valid])


def test_gaps_are_the_runs_of_missing_samples():
    take = mocap.read(SAMPLE)
    gaps = take.gaps()
    assert gaps, "the sample has gaps"
    valid = take.valid
    assert sum(g.length for g in gaps) == (~valid).sum()
    for g in gaps:
        run = valid[g.first_frame:g.first_frame + g.length, g.marker]
        assert not run.any()


def test_raw_positions_and_states_are_views_of_the_take():
    take = mocap.read(SMALL)
    view = take.raw_positions
    assert not view.flags["OWNDATA"]
    view[0, 0, :] = (1.0, 2.0, 3.0)
    take.valid[0, 0] = True
    assert tuple(take.positions[0, 0]) == (1.0, 2.0, 3.0)
    assert take.states.dtype == np.uint8
    del take
    assert view[0, 0, 1] == 2.0, "a view keeps its take alive"


def test_c3d_written_from_python_is_byte_identical_to_mocap_convert(tmp_path):
    ours = tmp_path / "python.c3d"
    theirs = tmp_path / "cli.c3d"
    mocap.read(SAMPLE).write(ours)
    subprocess.run([cli(), "convert", str(SAMPLE), str(theirs)], check=True, capture_output=True)
    assert ours.read_bytes() == theirs.read_bytes()


@pytest.mark.parametrize("suffix", [".trc", ".csv", ".bvh", ".fbx"])
def test_every_written_format_is_byte_identical_to_mocap_convert(tmp_path, suffix):
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    ours, theirs = tmp_path / "py" / ("take" + suffix), tmp_path / "cli" / ("take" + suffix)  # a TRC names its file
    mocap.read(SAMPLE).write(ours)
    subprocess.run([cli(), "convert", str(SAMPLE), str(theirs)], check=True, capture_output=True)
    assert ours.read_bytes() == theirs.read_bytes()


def test_arrays_round_trip_exactly_through_c3d_and_trc(tmp_path):
    take = mocap.read(SAMPLE)
    for name in ("round.c3d", "round.trc"):
        take.write(tmp_path / name)
        back = mocap.read(tmp_path / name)
        assert back.labels == take.labels
        assert np.array_equal(back.valid, take.valid)
        np.testing.assert_allclose(back.positions[take.valid], take.positions[take.valid], rtol=0, atol=1e-3)


def test_assigning_positions_sets_samples_and_nan_makes_gaps():
    take = mocap.Take(["a", "b"], 4, 60.0)
    values = np.arange(24, dtype=np.float64).reshape(4, 2, 3)
    values[2, 1, 0] = np.nan
    take.positions = values
    assert take.valid.sum() == 7
    assert not take.valid[2, 1]
    assert np.array_equal(take.positions[take.valid], values[take.valid])
    strided = np.zeros((8, 2, 3))[::2]
    take.positions = strided
    assert take.valid.all()


def test_wrong_arrays_raise_clear_errors():
    take = mocap.Take(["a"], 3, 100.0)
    with pytest.raises(TypeError, match="float64"):
        take.positions = np.zeros((3, 1, 3), dtype=np.int64)
    with pytest.raises(ValueError, match=r"\(3, 1, 3\)"):
        take.positions = np.zeros((3, 3))
    with pytest.raises(mocap.InvalidArgument, match="is not mm, cm or m"):
        take.units = "furlong"
    with pytest.raises(mocap.InvalidArgument):
        mocap.Take(["a"], -1, 100.0)


def test_bad_files_raise_the_core_errors_with_its_messages(tmp_path):
    with pytest.raises(mocap.IoError, match="nope.c3d"):
        mocap.read(tmp_path / "nope.c3d")
    corrupt = tmp_path / "corrupt.c3d"
    corrupt.write_bytes(b"\x02\x50" + b"\xff" * 100)
    with pytest.raises(mocap.FormatError, match="corrupt.c3d"):
        mocap.read(corrupt)
    assert issubclass(mocap.FormatError, mocap.Error)
    truncated = tmp_path / "truncated.c3d"
    truncated.write_bytes(SAMPLE.read_bytes()[:400000])
    take = mocap.read(truncated)
    assert take.data_loss, "a truncated file says data is missing"
    previous = tmp_path / "kept.c3d"
    previous.write_bytes(b"previous")
    with pytest.raises(mocap.Error):
        take.write(tmp_path / "kept.c3d" / "x.c3d")
    assert previous.read_bytes() == b"previous"


def resident_kb():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") // 1024


def test_reading_a_thousand_times_leaks_nothing():
    for _ in range(100):
        mocap.read(SMALL)
    before = resident_kb()
    for _ in range(1000):
        mocap.read(SMALL).positions
    assert resident_kb() - before < 2048, "RSS grew by more than 2 MB over 1 000 reads"


def test_analog_channels_and_events_are_the_files():
    path = SOURCE / "tests" / "data" / "c3d" / "sample01" / "Eb015pr.c3d"
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    info = json.loads(subprocess.run([cli, "info", str(path), "--json"], check=True, capture_output=True,
                                     text=True).stdout)
    analog = mocap.read(path).analog
    assert analog["rate"] == info["analog_rate"]
    assert [c["label"] for c in analog["channels"]] == info["analog_labels"]
    assert analog["stored"].shape == analog["physical"].shape and analog["stored"].shape[1] == 16
    c = analog["channels"][2]
    np.testing.assert_allclose(analog["physical"][:, 2],
                               (analog["stored"][:, 2] - c["offset"]) * c["scale"] * analog["general_scale"])
    assert mocap.read(SAMPLE).analog["stored"].shape[1] == 0
    events = mocap.read(path).events
    assert [{k: e[k] for k in ("label", "context", "time")} for e in events] == info["events"]
    assert [e["label"] for e in events] == ["RIC", "RHS", "RTO"]
