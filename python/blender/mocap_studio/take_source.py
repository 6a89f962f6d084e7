"""A take's samples for Blender, from the `mocap` module when Python can import it, else from the
`mocap` command line (its CSV export), so the add-on also works in Blender builds with their own
Python. Plain Python: no bpy here."""

import csv
import os
import shutil
import subprocess
import sys
import tempfile

METRES_PER_UNIT = {"mm": 0.001, "cm": 0.01, "m": 1.0}


class TakeSamples:
    """labels, rate (Hz), units ('mm'…), frames, and per marker: positions [(x, y, z) or None per
    frame] and states [int per frame, or None when the source has no states]."""

    def __init__(self, labels, rate, units, positions, states):
        self.labels = labels
        self.rate = rate
        self.units = units
        self.positions = positions
        self.states = states
        self.frames = len(positions[0]) if positions else 0


def import_mocap_module(extra_paths=()):
    """The `mocap` module, looked for on sys.path, then in `extra_paths` and $MOCAP_PYTHON_PATH
    (Blender ignores PYTHONPATH); None when it is nowhere."""
    try:
        import mocap
        return mocap
    except ImportError:
        pass
    candidates = list(extra_paths) + [p for p in os.environ.get("MOCAP_PYTHON_PATH", "").split(os.pathsep) if p]
    for folder in candidates:
        if folder and os.path.isdir(folder) and folder not in sys.path:
            sys.path.insert(0, folder)
            try:
                import mocap
                return mocap
            except ImportError:
                sys.path.remove(folder)
    return None


def find_cli(configured=""):
    """The `mocap` executable: the configured path, $MOCAP_CLI, or `mocap` on PATH."""
    for candidate in (configured, os.environ.get("MOCAP_CLI", ""), shutil.which("mocap") or ""):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


def samples_from_module(mocap, path):
    take = mocap.read(path)
    xyz = take.positions  # frames × markers × 3, NaN in gaps
    valid = take.valid
    states = take.states
    positions, state_lists = [], []
    for m in range(take.marker_count):
        positions.append([tuple(float(v) for v in xyz[f, m]) if valid[f, m] else None for f in range(take.frame_count)])
        state_lists.append([int(s) for s in states[:, m]])
    return TakeSamples(list(take.labels), take.rate, take.units, positions, state_lists)


def samples_from_cli(cli, path):
    """`mocap convert TAKE OUT.csv` (mm, empty cells in gaps) read back; no sample states."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "take.csv")
        run = subprocess.run([cli, "convert", path, out], capture_output=True, text=True)
        if run.returncode != 0:
            raise RuntimeError(run.stderr.strip() or "mocap convert failed")
        with open(out, newline="") as f:
            rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    labels = [header[c][:-2] for c in range(2, len(header), 3)]
    times = [float(row[1]) for row in body]
    rate = (len(times) - 1) / (times[-1] - times[0]) if len(times) > 1 and times[-1] > times[0] else 100.0
    positions = []
    for m in range(len(labels)):
        cells = [row[2 + 3 * m: 5 + 3 * m] for row in body]
        positions.append([None if "" in c else tuple(float(v) for v in c) for c in cells])
    return TakeSamples(labels, round(rate, 6), "mm", positions, None)


def read_take(path, module_paths=(), cli=""):
    """The take at `path` through the module, else the command line; raises RuntimeError saying
    which was missing when neither is there."""
    mocap = import_mocap_module(module_paths)
    if mocap is not None:
        return samples_from_module(mocap, path)
    executable = find_cli(cli)
    if executable is None:
        raise RuntimeError("neither the mocap Python module nor the mocap command line was found: set them in "
                           "the add-on's preferences, or MOCAP_PYTHON_PATH / MOCAP_CLI")
    return samples_from_cli(executable, path)
