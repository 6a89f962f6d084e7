#!/usr/bin/env python3
"""VMC over OSC as a real OSC tool reads it: `oscdump` (Debian's liblo-tools) receives what
`mocap stream --protocol vmc --markers` sends of the bundled take's first frames, and the test
parses its output: per frame every ARKit weight as /VMC/Ext/Blend/Val with the solve's value,
then /VMC/Ext/Blend/Apply, then a /VMC/Ext/Tra/Pos per marker with a sample, in metres.
Exit 77 (skipped, with the reason) without oscdump.

usage: vmc_oscdump_check.py MOCAP SAMPLE_DIR WORK_DIR
"""
import csv
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

STABILIZE = "root-1,root-2,root-3,root-4,root-5,root-6"
FRAMES = 20


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def wait_until_quiet(path, seconds=1.0, limit=30.0):
    """Until oscdump has written nothing for `seconds` (a busy machine prints slowly)."""
    start, size, since = time.monotonic(), -1, time.monotonic()
    while time.monotonic() - start < limit:
        now = path.stat().st_size
        if now != size:
            size, since = now, time.monotonic()
        elif time.monotonic() - since >= seconds:
            return
        time.sleep(0.1)


def main():
    if shutil.which("oscdump") is None:
        print("SKIPPED: oscdump is not installed (Debian package liblo-tools; scripts/setup.sh installs it)")
        return 77
    mocap, sample, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    take, rig = sample / "Facial-Sing.c3d", sample / "ict_face_rig.glb"
    solve_options = ["--binding", str(sample / "Facial-Sing.ict_face_rig.binding.json"), "--stabilize", STABILIZE]
    reference = work / "vmc_reference.csv"
    subprocess.run([mocap, "solve", "--mesh", str(rig), "--take", str(take), *solve_options, "--format", "livelink",
                    "-o", str(reference)], check=True, stdout=subprocess.DEVNULL)
    with open(reference, newline="") as f:
        rows = list(csv.DictReader(f))

    port = free_port()
    dumped = work / "oscdump.txt"
    with open(dumped, "w") as sink:
        dump = subprocess.Popen(["oscdump", "-L", str(port)], stdout=sink, stderr=subprocess.STDOUT)
        time.sleep(0.5)  # let oscdump bind its port
        stream = subprocess.run([mocap, "stream", str(take), "--rig", str(rig), *solve_options, "--protocol", "vmc",
                                 "--to", f"127.0.0.1:{port}", "--frames", f"1:{FRAMES}", "--markers"],
                                capture_output=True, text=True)
        wait_until_quiet(dumped)
        dump.terminate()
        dump.wait()
    out = dumped.read_text()
    if stream.returncode != 0:
        print(f"mocap stream exited with {stream.returncode}: {stream.stderr}")
        return 1

    # A frame is its weights, then Apply, then its markers: the next Val after an Apply starts the next.
    frames, current = [], {"weights": {}, "markers": {}}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) < 2:
            continue
        address = parts[1]  # parts[0] is the bundle's timetag
        if address == "/VMC/Ext/Blend/Val":
            if current.get("applied"):
                frames.append(current)
                current = {"weights": {}, "markers": {}}
            current["weights"][parts[3].strip('"')] = float(parts[4])
        elif address == "/VMC/Ext/Blend/Apply":
            current["applied"] = True
        elif address == "/VMC/Ext/Tra/Pos":
            current["markers"][parts[3].strip('"')] = [float(v) for v in parts[4:11]]
    frames.append(current)

    failures = []
    if len(frames) != FRAMES:
        failures.append(f"oscdump shows {len(frames)} frames, not {FRAMES}")
    worst = 0.0
    for i, frame in enumerate(frames[:FRAMES]):
        if len(frame["weights"]) != 52 or not frame.get("applied"):
            failures.append(f"frame {i}: {len(frame['weights'])} weights, applied: {frame.get('applied', False)}")
        for name, value in frame["weights"].items():
            worst = max(worst, abs(value - float(rows[i][name])))
        if not 20 <= len(frame["markers"]) <= 38:
            failures.append(f"frame {i}: {len(frame['markers'])} markers")
        for name, pos in frame["markers"].items():
            if not all(abs(c) < 5.0 for c in pos[:3]) or pos[3:] != [0.0, 0.0, 0.0, 1.0]:
                failures.append(f"frame {i}: marker {name} at {pos} (metres, identity rotation expected)")
                break
    # oscdump prints six decimals.
    if worst > 1e-6 + 5e-7:
        failures.append(f"a weight differs from the solve's by {worst}")
    print(f"[ measured ] oscdump read {len(frames)} VMC frames; {len(frames[0]['weights'])} weights and "
          f"{len(frames[0]['markers'])} markers in the first; largest weight difference {worst:.2e}")
    for failure in failures[:10]:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
