"""mocap.load_rig, mocap.read_binding and mocap.solve (ctest `python_module`)."""

import _thread
import csv
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"
RIG = SAMPLE_DIR / "ict_face_rig.glb"
BINDING = SAMPLE_DIR / "Facial-Sing.ict_face_rig.binding.json"


def cli():
    path = os.environ.get("MOCAP_CLI")
    if not path:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    return path


@pytest.fixture(scope="module")
def scene():
    rig = mocap.load_rig(RIG)
    return mocap.read(TAKE), rig, mocap.read_binding(BINDING, rig)


def test_the_solve_equals_the_command_lines(scene, tmp_path):
    take, rig, binding = scene
    assert rig.shape_count == 53 and len(rig.names) == 53
    result = mocap.solve(take, rig, binding)
    weights = result["weights"]
    assert weights.shape == (take.frame_count, 53)
    assert result["names"] == rig.names
    assert ((weights >= 0) & (weights <= 1)).all()
    out = tmp_path / "w.csv"
    subprocess.run([cli(), "solve", "--mesh", str(RIG), "--binding", str(BINDING), "--take", str(TAKE),
                    "--leave-out", "0", "-o", str(out)], check=True, capture_output=True)
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][2:] == rig.names
    theirs = np.array([[float(v) for v in row[2:]] for row in rows[1:]])
    np.testing.assert_allclose(weights, theirs, rtol=0, atol=1e-5)


def test_progress_is_reported_and_false_cancels(scene):
    take, rig, binding = scene
    seen = []
    mocap.solve(take, rig, binding, method="bvls", progress=seen.append)
    assert seen and seen == sorted(seen) and 0.0 <= seen[0] <= seen[-1] <= 1.0
    with pytest.raises(mocap.Cancelled):
        mocap.solve(take, rig, binding, method="bvls", progress=lambda fraction: False)


def test_ctrl_c_stops_the_solve_at_its_next_checkpoint(scene):
    take, rig, binding = scene
    calls = []

    def press_ctrl_c_then_go_slowly(fraction):
        calls.append(fraction)
        if len(calls) == 1:
            _thread.interrupt_main()  # as Ctrl+C does: a pending SIGINT, raised at once in Python
        time.sleep(0.06)  # past JobControl's 50 ms throttle: every checkpoint reports

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        mocap.solve(take, rig, binding, method="bvls", progress=press_ctrl_c_then_go_slowly)
    assert len(calls) == 1, "stopped at the checkpoint after the interrupt, not at the end"
    assert calls[0] < 0.5
    assert time.monotonic() - start < 1.0


def test_ctrl_c_while_the_core_works_stops_it(scene):
    take, rig, binding = scene
    start = time.monotonic()
    mocap.solve(take, rig, binding)  # the temporal solve: long enough to interrupt
    whole = time.monotonic() - start
    timer = threading.Timer(whole / 4, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        mocap.solve(take, rig, binding)
    timer.join()
    assert time.monotonic() - start < whole * 3 / 4 + 0.2, "stopped well before the end"


def test_bad_input_raises_clear_errors(scene, tmp_path):
    take, rig, binding = scene
    with pytest.raises(mocap.InvalidArgument, match="method 'magic'"):
        mocap.solve(take, rig, binding, method="magic")
    with pytest.raises(mocap.IoError):
        mocap.load_rig(tmp_path / "missing.glb")
    with pytest.raises(mocap.InvalidArgument, match="shapes="):
        mocap.load_rig(tmp_path / "neutral.obj")
    with pytest.raises(mocap.InvalidArgument, match="53 shapes"):
        rig.evaluate(np.zeros(3))
    assert rig.evaluate(np.zeros(53)).shape == (rig.vertex_count, 3)


def test_long_calls_let_other_python_threads_run(scene):
    take, rig, binding = scene

    def spins_while(work):
        worker = threading.Thread(target=work)
        start = time.monotonic()
        worker.start()
        spins = 0
        while worker.is_alive():
            spins += 1
        return spins / (time.monotonic() - start)

    # Holding the GIL, the core would leave this thread a switch interval (5 ms) now and then at best.
    assert spins_while(lambda: mocap.solve(take, rig, binding, method="bvls")) > 100000
    assert spins_while(lambda: mocap.clean(mocap.read(TAKE))) > 100000
