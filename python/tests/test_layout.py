"""mocap.plan_layout: marker layout planning as `mocap pfa` runs it (ctest `python_module`)."""

import json
import os
import pathlib
import subprocess

import pytest

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
TAKE = SOURCE / "resources" / "sample" / "Facial-Sing.c3d"
RIG = SOURCE / "resources" / "sample" / "ict_face_rig.glb"
BINDING = SOURCE / "resources" / "sample" / "Facial-Sing.ict_face_rig.binding.json"
HEAD = ["root-%d" % i for i in range(1, 7)]


def pfa_cli(*args):
    cli = os.environ.get("MOCAP_CLI")
    if not cli:
        pytest.skip("MOCAP_CLI is not set (ctest sets it to build/bin/mocap)")
    run = subprocess.run([cli, "pfa", str(TAKE), "--json", *map(str, args)], check=True, capture_output=True, text=True)
    return json.loads(run.stdout)


def same_layout(ours, theirs):
    if theirs is None:
        return ours is None
    keys = [k for k in ("labels", "k", "stability", "blendshape_mse", "reconstruction_rmse_mm") if k in ours]
    return all(ours[k] == theirs[k] for k in keys) and len(keys) >= 3


@pytest.mark.parametrize("method", ["pfa", "greedy"])
def test_plan_layout_reports_what_mocap_pfa_reports(method):
    theirs = pfa_cli("--method", method, "--restarts", 20, "--random", 3, "--stabilize", ",".join(HEAD))
    ours = mocap.plan_layout(mocap.read(TAKE), method=method, restarts=20, random=3, stabilize=HEAD)
    for key in ("method", "markers", "frames", "pca", "motion_rms_mm", "cancelled"):
        assert ours[key] == theirs[key], key
    assert len(ours["sizes"]) == len(theirs["sizes"]) > 3
    for mine, cli in zip(ours["sizes"], theirs["sizes"]):
        assert mine["markers"] == cli["markers"]
        for which in ("selected", "pfa", "greedy"):
            assert same_layout(mine[which], cli[which]), (mine["markers"], which)
        assert mine["random"]["count"] == cli["random"]["count"]
        if cli["random"]["count"]:
            assert mine["random"]["blendshape_mse"] == cli["random"]["blendshape_mse"]
        else:
            assert mine["random"]["blendshape_mse"] is None and cli["random"]["blendshape_mse"] is None
    rec = ours["recommended"]
    assert {k: rec[k] for k in ("markers", "rule", "labels")} == theirs["recommended"]
    assert set(rec["capture_labels"]) == set(rec["labels"]) | set(HEAD)


def test_plan_layout_judges_on_a_rig_as_mocap_pfa_rig_does():
    shapes = mocap.load_rig(RIG).names[:12]
    plan = ("--stabilize", ",".join(HEAD), "--markers", "section*", "--restarts", 10, "--random", 2)
    theirs = pfa_cli(*plan, "--rig", RIG, "--binding", BINDING, "--rig-only", ",".join(shapes), "--rig-frames", 120)
    rig = mocap.load_rig(RIG, only=shapes)
    seen = []
    ours = mocap.plan_layout(mocap.read(TAKE), stabilize=HEAD, markers=["section*"], restarts=10, random=2, rig=rig,
                             binding=mocap.read_binding(BINDING, rig), rig_frames=120, progress=seen.append)
    summary = {k: v for k, v in theirs["rig"].items() if k not in ("path", "seconds")}
    assert {k: v for k, v in ours["rig"].items() if k != "seconds"} == summary
    assert ours["rig"]["method"] == "bvls" and ours["rig"]["bound_markers"] > 20
    judged = 0
    for mine, cli in zip(ours["sizes"], theirs["sizes"]):
        for which in ("selected", "pfa", "greedy"):
            if cli[which] is not None:
                assert mine[which]["rig_weight_mse"] == cli[which]["rig_weight_mse"], (mine["markers"], which)
                judged += mine[which]["rig_weight_mse"] is not None
        assert mine["random"]["rig_weight_mse"] == cli["random"]["rig_weight_mse"]
        assert mine["random"]["rig_count"] == cli["random"]["rig_count"]
    assert judged > 20
    greedy = [s["greedy"]["rig_weight_mse"] for s in ours["sizes"] if s["greedy"] and s["greedy"]["rig_weight_mse"]]
    assert greedy[0] > greedy[-1], "three markers judge worse than thirty"
    assert seen == sorted(seen) and seen[-1] > 0.5, "the rig measure reports the second half"
    without = mocap.plan_layout(mocap.read(TAKE), stabilize=HEAD, markers=["section*"], restarts=10, random=2)
    assert without["rig"] is None and without["sizes"][-1]["pfa"]["rig_weight_mse"] is None


def test_bad_rig_requests_are_clear_errors_before_any_planning():
    take = mocap.read(TAKE)
    rig = mocap.load_rig(RIG)
    binding = mocap.read_binding(BINDING, rig)
    face_binding = mocap.read_binding(SOURCE / "resources" / "sample" / "Facial-Sing.binding.json",
                                      SOURCE / "resources" / "sample" / "canonical_face_model.obj")
    with pytest.raises(mocap.InvalidArgument, match="needs binding="):
        mocap.plan_layout(take, rig=rig)
    with pytest.raises(mocap.InvalidArgument, match="binding needs rig="):
        mocap.plan_layout(take, binding=binding)
    with pytest.raises(mocap.InvalidArgument, match="rig_frames needs rig="):
        mocap.plan_layout(take, rig_frames=10)
    with pytest.raises(mocap.InvalidArgument, match="468 vertices"):
        mocap.plan_layout(take, rig=rig, binding=face_binding)
    with pytest.raises(mocap.InvalidArgument, match="rig_method 'magic'"):
        mocap.plan_layout(take, rig=rig, binding=binding, rig_method="magic")
    with pytest.raises(mocap.InvalidArgument, match="rig_frames"):
        mocap.plan_layout(take, rig=rig, binding=binding, rig_frames=-1)
    with pytest.raises(TypeError, match="mocap.Rig"):
        mocap.plan_layout(take, rig=str(RIG), binding=binding)


def test_plan_layout_progress_and_cancel():
    take = mocap.read(TAKE)
    seen = []
    mocap.plan_layout(take, restarts=50, random=2, progress=seen.append)
    assert seen and seen == sorted(seen)
    with pytest.raises(mocap.Cancelled):
        mocap.plan_layout(take, restarts=2000, progress=lambda f: False)


def test_bad_layout_requests_are_clear_errors():
    take = mocap.read(TAKE)
    with pytest.raises(mocap.InvalidArgument, match="method"):
        mocap.plan_layout(take, method="best")
    with pytest.raises(mocap.InvalidArgument, match="nosuch"):
        mocap.plan_layout(take, markers=["nosuch*"])
    with pytest.raises(mocap.InvalidArgument, match="k must"):
        mocap.plan_layout(take, k=(5, 2))
    with pytest.raises(mocap.InvalidArgument, match="variance"):
        mocap.plan_layout(take, variance=float("nan"))
    with pytest.raises(mocap.InvalidArgument):
        mocap.plan_layout(take, keyposes="x:y")
    with pytest.raises(mocap.InvalidArgument, match="needs a take"):
        mocap.plan_layout([])
    with pytest.raises(mocap.IoError):
        mocap.plan_layout(take, pairs="/nonexistent/pairs.json")
    with pytest.raises(TypeError):
        mocap.plan_layout(["not a take"])
