"""The README's pipeline example runs as written (ctest `python_module`): read, clean with a preset,
solve, write FBX and CSV. The block is the first ```python block after the README's marker comment
`<!-- pipeline example -->`; it runs in a scratch folder that sees the repository's resources/."""

import csv
import os
import pathlib
import runpy

import mocap

SOURCE = pathlib.Path(os.environ.get("MOCAP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def readme_example():
    text = (SOURCE / "README.md").read_text(encoding="utf-8")
    after = text[text.index("<!-- pipeline example -->"):]
    start = after.index("```python\n") + len("```python\n")
    return after[start:after.index("```", start)]


def test_the_readme_pipeline_example_runs_and_writes_its_files(tmp_path, monkeypatch, capsys):
    code = readme_example()
    lines = [line for line in code.splitlines() if line.strip()]
    assert len(lines) <= 20, "the README promises a 20-line example, this one has %d" % len(lines)
    (tmp_path / "resources").symlink_to(SOURCE / "resources")
    script = tmp_path / "pipeline.py"
    script.write_text(code)
    monkeypatch.chdir(tmp_path)
    runpy.run_path(str(script), run_name="__main__")

    cleaned = mocap.read(tmp_path / "Facial-Sing.cleaned.c3d")
    assert [h["operation"] for h in cleaned.history][:2] == ["repair spikes", "fill gaps"]
    assert (tmp_path / "Facial-Sing.fbx").read_bytes().startswith(b"Kaydara FBX Binary")
    with open(tmp_path / "Facial-Sing.weights.csv", newline="") as f:
        rows = list(csv.reader(f))
    rig = mocap.load_rig(SOURCE / "resources" / "sample" / "ict_face_rig.glb")
    assert rows[0][:2] == ["Frame", "Time"] and rows[0][2:] == rig.names
    assert len(rows) - 1 == cleaned.frame_count
    assert "3000 frames of 53 shapes" in capsys.readouterr().out
