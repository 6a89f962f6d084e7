"""mocap.clean: the `mocap clean` pipeline from Python (ctest `python_module`)."""

import _thread
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE = SOURCE / "resources" / "sample" / "Facial-Sing.c3d"


def cli():
    path = os.environ.get("MOCAP_CLI")
    if not path:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    return path


def without_paths(report):
    return {k: v for k, v in report.items() if k not in ("input", "output")}


def test_clean_gives_the_samples_and_report_of_the_command_line(tmp_path):
    out, report_path = tmp_path / "cli.c3d", tmp_path / "report.json"
    subprocess.run([cli(), "clean", str(SAMPLE), "-o", str(out), "--max-gap-seconds", "1", "--report", str(report_path)],
                   check=True, capture_output=True)
    theirs = mocap.read(out)
    take = mocap.read(SAMPLE)
    report = mocap.clean(take, fill={"max_gap_seconds": 1})
    assert np.array_equal(take.valid, theirs.valid)
    assert np.array_equal(take.states, theirs.states)
    np.testing.assert_allclose(take.positions[take.valid], theirs.positions[theirs.valid], rtol=0, atol=1e-4)
    assert without_paths(report) == without_paths(json.loads(report_path.read_text()))
    assert report["fill"]["filled_samples"] > 0
    assert take.history[-1]["tool"] == "mocap python"


def test_a_preset_file_and_keywords_combine_keywords_winning(tmp_path):
    preset = tmp_path / "preset.json"
    preset.write_text(json.dumps({"format": "mocap-clean-preset", "version": 1, "smooth": {"method": "off"},
                                  "spikes": {"method": "off"}}))
    take = mocap.read(SAMPLE)
    report = mocap.clean(take, preset, spikes={"method": "robust"})
    assert report["smooth"]["method"] == "off"
    assert report["spikes"]["method"] == "robust"
    take = mocap.read(SAMPLE)
    report = mocap.clean(take, {"fill": {"method": "off"}}, smooth="off", spikes="off")
    assert (report["fill"]["method"], report["smooth"]["method"], report["spikes"]["method"]) == ("off", "off", "off")
    assert report["fill"]["filled_samples"] == 0


def test_bad_options_name_the_key():
    take = mocap.read(SAMPLE)
    with pytest.raises(mocap.InvalidArgument, match="smoth"):
        mocap.clean(take, smoth="off")
    with pytest.raises(mocap.InvalidArgument, match="spikes.factor"):
        mocap.clean(take, spikes={"factor": "big"})
    with pytest.raises(mocap.IoError):
        mocap.clean(take, "/nonexistent/preset.json")


def test_clean_reports_progress_and_a_cancel_leaves_the_take_as_it_was():
    take = mocap.read(SAMPLE)
    before, history = take.positions.copy(), len(take.history)
    seen = []
    mocap.clean(take, progress=seen.append)
    assert seen and seen == sorted(seen) and 0.0 <= seen[0] <= seen[-1] <= 1.0

    take = mocap.read(SAMPLE)
    view = take.raw_positions  # a view of the take's own memory stays valid through a clean
    with pytest.raises(mocap.Cancelled):
        mocap.clean(take, progress=lambda fraction: False)
    np.testing.assert_array_equal(take.positions, before)
    assert len(take.history) == history, "nothing recorded for a clean that did not happen"

    calls = []

    def press_ctrl_c(fraction):
        calls.append(fraction)
        if len(calls) == 1:
            _thread.interrupt_main()  # as Ctrl+C does

    with pytest.raises(KeyboardInterrupt):
        mocap.clean(take, progress=press_ctrl_c)
    np.testing.assert_array_equal(take.positions, before)
    mocap.clean(take)
    assert len(take.history) > history
    assert np.array_equal(np.asarray(view), take.raw_positions), "the view sees the cleaned samples"
