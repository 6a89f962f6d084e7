"""The single cleaning steps from Python: `mocap clean` with one step on (ctest `python_module`)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE = SOURCE / "resources" / "sample" / "Facial-Sing.c3d"
HEAD = ["root-1", "root-2", "root-3", "root-4"]


def clean_cli(tmp_path, *args):
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    out, report = tmp_path / "cli.c3d", tmp_path / "cli.json"
    subprocess.run([cli, "clean", str(SAMPLE), "-o", str(out), "--report", str(report), *map(str, args)],
                   check=True, capture_output=True)
    return mocap.read(out), json.loads(report.read_text())


def section(report, step):
    return {**report[step], "valid_fraction": report["valid_fraction"], "model_outputs": report["model_outputs"]}


def assert_same_samples(take, theirs):
    assert np.array_equal(take.valid, theirs.valid)
    assert np.array_equal(take.states, theirs.states)
    np.testing.assert_allclose(take.positions[take.valid], theirs.positions[theirs.valid], rtol=0, atol=1e-4)


@pytest.mark.parametrize("step, run, cli_args", [
    ("spikes", lambda t: mocap.detect_spikes(t, threshold=5), ("--fill", "off", "--smooth", "off",
                                                               "--spike-threshold", 5)),
    ("fill", lambda t: mocap.fill_gaps(t, method="linear", max_gap=100),
     ("--spikes", "off", "--smooth", "off", "--fill", "linear", "--max-gap", 100)),
    ("smooth", lambda t: mocap.smooth(t, method="butterworth", cutoff_hz=8),
     ("--spikes", "off", "--fill", "off", "--smooth", "butterworth", "--cutoff", 8)),
    ("stabilize", lambda t: mocap.stabilize(t, markers=HEAD),
     ("--spikes", "off", "--fill", "off", "--smooth", "off", "--stabilize", ",".join(HEAD), "--keep-stabilized")),
])
def test_a_step_gives_the_samples_and_report_of_mocap_clean_with_only_it_on(tmp_path, step, run, cli_args):
    theirs, cli_report = clean_cli(tmp_path, *cli_args)
    take = mocap.read(SAMPLE)
    report = run(take)
    assert_same_samples(take, theirs)
    assert report == section(cli_report, step)
    recorded = [[{k: h[k] for k in ("operation", "parameters", "samples")} for h in t.history] for t in (take, theirs)]
    assert recorded[0] == recorded[1]


def test_the_steps_change_what_they_report():
    take = mocap.read(SAMPLE)
    assert mocap.detect_spikes(take)["repaired_samples"] > 0
    assert mocap.fill_gaps(take)["filled_samples"] > 0
    assert mocap.smooth(take)["smoothed_samples"] > 0
    assert mocap.stabilize(take, HEAD)["markers"] == HEAD
    assert [h["operation"] for h in take.history] == ["repair spikes", "fill gaps", "smooth", "stabilize head"]


def test_detect_spikes_without_repair_leaves_the_take_as_it_was():
    take, repaired = mocap.read(SAMPLE), mocap.read(SAMPLE)
    before = take.raw_positions.copy()
    found = mocap.detect_spikes(take, repair=False)
    assert found["count"] > 0 and found["repaired_samples"] == 0
    assert np.array_equal(take.raw_positions, before) and take.history == []
    assert mocap.detect_spikes(repaired)["flagged"] == found["flagged"]


def test_fill_gaps_on_a_selection_changes_only_those_samples_as_the_whole_fill_would():
    whole, take = mocap.read(SAMPLE), mocap.read(SAMPLE)
    before = take.raw_positions.copy()
    mocap.fill_gaps(whole, max_gap=100)
    first = take.first_frame
    report = mocap.fill_gaps(take, max_gap=100, markers=["section4-2"], frames=(1100 + first, 1130 + first))
    m = take.labels.index("section4-2")
    changed = np.argwhere(np.any(take.raw_positions != before, axis=2))
    assert len(changed) == report["filled_samples"] > 0
    assert set(changed[:, 1]) == {m}
    assert changed[:, 0].min() >= 1100 and changed[:, 0].max() <= 1130
    np.testing.assert_array_equal(take.raw_positions[changed[:, 0], m], whole.raw_positions[changed[:, 0], m])
    assert {g["marker"] for g in report["gaps"]} == {"section4-2"}
    step = take.history[-1]
    assert (step["markers"], step["first_frame"], step["last_frame"]) == (["section4-2"], 1100 + first, 1130 + first)


def changed_samples(take, before):
    return np.argwhere(np.any(take.raw_positions != before, axis=2))


def test_smooth_on_a_selection_changes_only_those_samples_as_the_whole_smooth_would():
    whole, take = mocap.read(SAMPLE), mocap.read(SAMPLE)
    before, states_before = take.raw_positions.copy(), take.states.copy()
    mocap.smooth(whole, method="butterworth", cutoff_hz=6)
    first = take.first_frame
    markers = ["section4-2", "section7-1"]
    report = mocap.smooth(take, method="butterworth", cutoff_hz=6, markers=markers,
                          frames=(500 + first, 899 + first))
    changed = changed_samples(take, before)
    assert len(changed) == report["smoothed_samples"] > 0
    assert {take.labels[m] for m in changed[:, 1]} == set(markers)
    assert changed[:, 0].min() >= 500 and changed[:, 0].max() <= 899
    frames, markers_at = changed[:, 0], changed[:, 1]
    np.testing.assert_array_equal(take.raw_positions[frames, markers_at], whole.raw_positions[frames, markers_at])
    inside = np.zeros(take.valid.shape, bool)
    inside[500:900, [take.labels.index(m) for m in markers]] = True
    assert np.array_equal(take.states[~inside], states_before[~inside]), "no state changes outside"
    assert np.array_equal(take.states[inside], whole.states[inside])
    step = take.history[-1]
    assert step["operation"] == "smooth" and step["samples"] == report["smoothed_samples"]
    assert (step["markers"], step["first_frame"], step["last_frame"]) == (markers, 500 + first, 899 + first)


def test_detect_spikes_on_a_selection_flags_and_repairs_only_there():
    whole, take = mocap.read(SAMPLE), mocap.read(SAMPLE)
    everywhere = mocap.detect_spikes(whole, threshold=3)
    flagged = everywhere["flagged"]
    assert len({f["marker"] for f in flagged}) >= 2, "the sample has spikes on several markers"
    marker = flagged[0]["marker"]
    mine = [f for f in flagged if f["marker"] == marker]
    frames = (min(f["frame"] for f in mine), max(f["frame"] for f in mine))
    before = take.raw_positions.copy()
    found = mocap.detect_spikes(take, threshold=3, repair=False, markers=[marker], frames=frames)
    assert found["flagged"] == mine and found["count"] == len(mine)
    assert np.array_equal(take.raw_positions, before) and take.history == []
    report = mocap.detect_spikes(take, threshold=3, markers=[marker], frames=frames)
    assert report["flagged"] == mine
    changed = changed_samples(take, before)
    assert len(changed) == report["repaired_samples"] > 0
    assert {take.labels[m] for m in changed[:, 1]} == {marker}
    first = take.first_frame
    assert frames[0] - first <= changed[:, 0].min() and changed[:, 0].max() <= frames[1] - first
    np.testing.assert_array_equal(take.raw_positions[changed[:, 0], changed[:, 1]],
                                  whole.raw_positions[changed[:, 0], changed[:, 1]])
    step = take.history[-1]
    assert (step["operation"], step["markers"], step["first_frame"], step["last_frame"]) == \
        ("repair spikes", [marker], frames[0], frames[1])


def test_a_stopped_step_on_a_selection_leaves_the_take_as_it_was():
    take = mocap.read(SAMPLE)
    before = take.raw_positions.copy()
    with pytest.raises(mocap.Cancelled):
        mocap.smooth(take, markers=["section4-2"], progress=lambda f: False)
    with pytest.raises(mocap.Cancelled):
        mocap.fill_gaps(take, frames=(take.first_frame, take.first_frame + 2999), progress=lambda f: False)
    assert np.array_equal(take.raw_positions, before) and take.history == []


def test_bad_step_arguments_are_clear_errors():
    take = mocap.read(SAMPLE)
    with pytest.raises(mocap.InvalidArgument, match="factr"):
        mocap.detect_spikes(take, factr=2)
    with pytest.raises(mocap.InvalidArgument, match="method"):
        mocap.fill_gaps(take, method="magic")
    with pytest.raises(mocap.InvalidArgument, match="nosuchmarker"):
        mocap.fill_gaps(take, markers=["nosuchmarker"])
    with pytest.raises(mocap.InvalidArgument, match="frames"):
        mocap.fill_gaps(take, frames=(10, 5))
    with pytest.raises(mocap.InvalidArgument, match="frames"):
        mocap.fill_gaps(take, frames=(0, 10**6))
    with pytest.raises(mocap.InvalidArgument, match="head markers"):
        mocap.stabilize(take)
    with pytest.raises(mocap.InvalidArgument, match="NaN"):
        mocap.smooth(take, method="butterworth", cutoff_hz=float("nan"))
    with pytest.raises(mocap.InvalidArgument, match="NaN"):
        mocap.clean(take, fill={"max_gap_seconds": float("inf")})
    with pytest.raises(TypeError):
        mocap.fill_gaps(take, frames="all")
    with pytest.raises(mocap.InvalidArgument, match="nosuchmarker"):
        mocap.smooth(take, markers=["nosuchmarker"])
    with pytest.raises(mocap.InvalidArgument, match="frames"):
        mocap.detect_spikes(take, frames=(5, 1))
    with pytest.raises(mocap.InvalidArgument, match="frames"):
        mocap.smooth(take, frames=(0, 10**6))
    assert take.history == []
