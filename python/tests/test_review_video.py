"""mocap.write_review_video: `mocap review`'s video from Python, through the command line (the
rendering is the studio's Qt/VTK view, which the module does not load). ctest `python_module`;
the rendering tests skip, saying so, when the build has no mocap-review (MOCAP_BUILD_GUI off)."""

import os
import pathlib

import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SAMPLE_DIR = SOURCE / "resources" / "sample"
TAKE = SAMPLE_DIR / "Facial-Sing.c3d"


def review_cli():
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    if not os.access(pathlib.Path(cli).with_name("mocap-review"), os.X_OK):
        pytest.skip("no mocap-review beside %s (it is built with the studio, MOCAP_BUILD_GUI)" % cli)
    return cli


def test_a_review_of_a_take_from_python(tmp_path):
    cli = review_cli()
    take = mocap.read(TAKE)
    mocap.smooth(take, markers=["section4-2"])  # a take changed in Python is what gets reviewed
    first = take.first_frame
    seen = []
    summary = mocap.write_review_video(tmp_path / "review.mp4", take, frames=(first + 100, first + 139),
                                       size=(320, 240), select=["section4-2"], progress=seen.append, cli=cli)
    written = pathlib.Path(summary["output"])
    assert written.exists() and written.stat().st_size > 1000
    assert written.parent == tmp_path and written.stem == "review"
    assert (summary["frames"], summary["width"], summary["height"]) == (40, 320, 240)
    assert summary["frame_rate"] == take.rate
    assert summary["codec"] in ("avc1", "mp4v", "MJPG")
    assert seen and seen == sorted(seen) and seen[-1] == 1.0


def test_a_review_with_the_solved_rig_from_paths_found_on_its_own(tmp_path, monkeypatch):
    cli = review_cli()
    monkeypatch.setenv("MOCAP_CLI", cli)
    rig = SAMPLE_DIR / "ict_face_rig.glb"
    binding = mocap.read_binding(SAMPLE_DIR / "Facial-Sing.ict_face_rig.binding.json", mocap.load_rig(rig))
    first = mocap.read(TAKE).first_frame
    summary = mocap.write_review_video(tmp_path / "rig.avi", TAKE, frames=(first, first + 9), size="256x192",
                                       solve=rig, binding=binding)
    assert summary["container"] == "avi" and summary["frames"] == 10
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rig.avi"]


def test_a_stopped_review_leaves_no_file(tmp_path):
    cli = review_cli()
    first = mocap.read(TAKE).first_frame
    calls = []

    def stop_at_once(fraction):
        calls.append(fraction)
        return False

    with pytest.raises(mocap.Cancelled):
        mocap.write_review_video(tmp_path / "stopped.mp4", TAKE, frames=(first, first + 399), size=(256, 192),
                                 progress=stop_at_once, cli=cli)
    assert calls and calls[0] < 1.0
    assert list(tmp_path.iterdir()) == [], "no partial video or temporary file is left"


def test_bad_review_requests_are_clear_errors_and_write_nothing(tmp_path):
    with pytest.raises(mocap.IoError, match="pass cli= or set MOCAP_CLI"):
        mocap.write_review_video(tmp_path / "x.mp4", TAKE, cli=tmp_path / "no-mocap-here")
    cli = review_cli()
    with pytest.raises(mocap.InvalidArgument, match="--size"):
        mocap.write_review_video(tmp_path / "x.mp4", TAKE, size=(321, 240), cli=cli)
    with pytest.raises(mocap.IoError, match="missing.c3d"):
        mocap.write_review_video(tmp_path / "x.mp4", tmp_path / "missing.c3d", cli=cli)
    with pytest.raises(mocap.InvalidArgument, match="--frames"):
        mocap.write_review_video(tmp_path / "x.mp4", TAKE, frames=(10, 10**6), cli=cli)
    assert list(tmp_path.iterdir()) == []
