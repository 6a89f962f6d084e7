#!/usr/bin/env python3
"""A Live Link Face receiver in plain Python (standard library only), run by ctest: it solves the
bundled take with `mocap solve --format livelink` for reference values, then receives what
`mocap stream` sends of the same solve over loopback and checks every datagram: the layout as the
public receivers decode it, frame numbers in order with none dropped, the subject and the rate,
and each of the 61 values against the solve's Live Link CSV within 1e-6. It prints how late the
datagrams arrived against the schedule (the first one's arrival plus i / rate).

usage: live_link_receiver.py MOCAP SAMPLE_DIR WORK_DIR
"""
import csv
import json
import socket
import struct
import subprocess
import sys
import time
from pathlib import Path

# The packet's value order (Unreal's EARFaceBlendShape), written out here from the public
# description rather than taken from our code, so a wrong order in the sender fails this test.
PACKET_NAMES = """EyeBlinkLeft EyeLookDownLeft EyeLookInLeft EyeLookOutLeft EyeLookUpLeft EyeSquintLeft EyeWideLeft
EyeBlinkRight EyeLookDownRight EyeLookInRight EyeLookOutRight EyeLookUpRight EyeSquintRight EyeWideRight
JawForward JawLeft JawRight JawOpen MouthClose MouthFunnel MouthPucker MouthLeft MouthRight MouthSmileLeft
MouthSmileRight MouthFrownLeft MouthFrownRight MouthDimpleLeft MouthDimpleRight MouthStretchLeft MouthStretchRight
MouthRollLower MouthRollUpper MouthShrugLower MouthShrugUpper MouthPressLeft MouthPressRight MouthLowerDownLeft
MouthLowerDownRight MouthUpperUpLeft MouthUpperUpRight BrowDownLeft BrowDownRight BrowInnerUp BrowOuterUpLeft
BrowOuterUpRight CheekPuff CheekSquintLeft CheekSquintRight NoseSneerLeft NoseSneerRight TongueOut HeadYaw
HeadPitch HeadRoll LeftEyeYaw LeftEyePitch LeftEyeRoll RightEyeYaw RightEyePitch RightEyeRoll""".split()
assert len(PACKET_NAMES) == 61

STABILIZE = "root-1,root-2,root-3,root-4,root-5,root-6"


def decode(datagram):
    """version u8, device id and subject (u32 length + bytes), frame i32, sub-frame f32,
    rate numerator and denominator i32, count u8, 61 f32; all big-endian."""
    offset = 0
    (version,) = struct.unpack_from(">B", datagram, offset)
    offset += 1
    strings = []
    for _ in range(2):
        (length,) = struct.unpack_from(">I", datagram, offset)
        offset += 4
        strings.append(datagram[offset:offset + length].decode("utf-8"))
        offset += length
    frame, sub_frame, numerator, denominator, count = struct.unpack_from(">ifiiB", datagram, offset)
    offset += 17
    values = struct.unpack_from(">61f", datagram, offset)
    offset += 61 * 4
    if offset != len(datagram):
        raise ValueError(f"{len(datagram) - offset} bytes left over")
    return version, strings[0], strings[1], frame, sub_frame, numerator, denominator, count, values


def main():
    mocap, sample, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    take = sample / "Facial-Sing.c3d"
    rig = sample / "ict_face_rig.glb"
    binding = sample / "Facial-Sing.ict_face_rig.binding.json"
    reference = work / "reference_livelink.csv"
    solve_options = ["--binding", str(binding), "--stabilize", STABILIZE]
    subprocess.run([mocap, "solve", "--mesh", str(rig), "--take", str(take), *solve_options, "--format", "livelink",
                    "-o", str(reference)], check=True, stdout=subprocess.DEVNULL)
    with open(reference, newline="") as f:
        rows = list(csv.DictReader(f))

    receiver = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    receiver.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4 << 20)
    receiver.bind(("127.0.0.1", 0))
    port = receiver.getsockname()[1]
    receiver.settimeout(1.0)
    stream = subprocess.Popen([mocap, "stream", str(take), "--rig", str(rig), *solve_options, "--protocol",
                               "livelink", "--to", f"127.0.0.1:{port}", "--subject", "SingFace", "--json"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    datagrams = []
    while True:
        try:
            data = receiver.recv(65536)
            datagrams.append((time.monotonic(), data))
        except socket.timeout:
            if stream.poll() is not None:
                break
    out, err = stream.communicate()
    if stream.returncode != 0:
        print(f"mocap stream exited with {stream.returncode}: {err}")
        return 1
    report = json.loads(out)

    failures = []
    if len(datagrams) != len(rows):
        failures.append(f"received {len(datagrams)} datagrams for {len(rows)} frames")
    worst = 0.0
    first_frame = None
    for i, (_, data) in enumerate(datagrams[:len(rows)]):
        version, device, subject, frame, sub_frame, numerator, denominator, count, values = decode(data)
        if i == 0:
            first_frame = frame
        if (version, len(device), subject, count, numerator, denominator) != (6, 36, "SingFace", 61, 100, 1):
            failures.append(f"datagram {i}: version {version}, device id of {len(device)}, subject {subject!r}, "
                            f"{count} values, rate {numerator}/{denominator}")
        if frame != first_frame + i:
            failures.append(f"datagram {i} carries frame {frame}, not {first_frame + i}")
        for name, value in zip(PACKET_NAMES, values):
            worst = max(worst, abs(value - float(rows[i][name])))
        if len(failures) > 5:
            break
    if worst > 1e-6:
        failures.append(f"a value differs from the solve's by {worst}")
    if first_frame != 1:
        failures.append(f"the first datagram carries frame {first_frame}, not the take's first frame 1")

    rate = report["rate"]
    late_ms = [1000.0 * ((t - datagrams[0][0]) - i / rate) for i, (t, _) in enumerate(datagrams)]
    ordered = sorted(late_ms)
    p95 = ordered[int(0.95 * len(ordered))] if ordered else float("nan")
    tail = sorted(late_ms[-100:])
    tail_median = tail[len(tail) // 2] if tail else float("nan")
    print(f"[ measured ] {len(datagrams)} datagrams of {len(rows)} frames over {report['seconds']:.3f} s; arrival "
          f"against the schedule (first arrival + i/rate): p95 {p95:.3f} ms, max {ordered[-1]:.3f} ms, last "
          f"{late_ms[-1]:.3f} ms, median of the last 100 {tail_median:.3f} ms; sender's own lateness: "
          f"{json.dumps(report['lateness_ms'])}; largest value difference {worst:.2e}")
    if report["datagrams_sent"] != len(rows) or report["datagrams_refused"] != 0:
        failures.append(f"the sender reports {report['datagrams_sent']} sent, {report['datagrams_refused']} refused")
    # No drift over the take: the end is as punctual as the start (a single late wake-up on a busy
    # machine is not drift, so the median of the last 100 is judged, not the last one alone).
    if not tail_median < 5.0:
        failures.append(f"the stream drifted: the last 100 datagrams arrived {tail_median:.3f} ms late (median)")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
