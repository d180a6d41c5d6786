#!/usr/bin/env bash
# Progress under a pseudo-terminal: the rate (cases/s) and the time left, refreshed several times
# a second; none when standard error is not a terminal or with -q; an interrupt prints one line
# saying what was kept. The sweep (225,741 cases, about 2 s on one thread in the Release build)
# outlasts the interrupt at 0.5 s and shows several refreshes.
set -uo pipefail
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
sed -e 's|"sweep": .*|"sweep": {"tY_mm": {"from": -6, "to": 10, "step": 0.01}, "Q_kN": {"from": 10, "to": 150, "step": 1}}|' \
    -e "s|\"\\.\\./profiles/|\"$src/profiles/|g" "$src/cases/manchester.json" > "$tmp/big.json"
python3 - "$bin" "$tmp" "$src" <<'PY'
import os, pty, re, select, signal, subprocess, sys, time
bin, tmp, src = sys.argv[1], sys.argv[2], sys.argv[3]

def run(args, interrupt_after=None):
    pid, fd = pty.fork()
    if pid == 0:
        os.execv(bin, [bin] + args)
    out, t0, sent = b"", time.time(), False
    while True:
        # The interrupt once the run has started its sweep (its progress shown), not before: a
        # slow start (a sanitizer build on a busy machine) must not be interrupted while it is
        # still reading its inputs, before its output directory has a message to give.
        if interrupt_after is not None and not sent and time.time() - t0 > interrupt_after and b"cases/s" in out:
            os.kill(pid, signal.SIGINT); sent = True
        r, _, _ = select.select([fd], [], [], 0.1)
        if r:
            try:
                data = os.read(fd, 65536)
            except OSError:
                break
            if not data:
                break
            out += data
    _, status = os.waitpid(pid, 0)
    return out.decode(errors="replace"), status

out, status = run(["run", tmp + "/big.json", "-o", tmp + "/out", "--format", "csv", "--threads", "1"])
assert os.WEXITSTATUS(status) == 0, (status, out)
lines = [l for l in re.split(r"[\r\n]", out) if l.startswith("mhcontact run: ") and "cases/s" in l]
assert lines, out
assert re.search(r"\d+/\d+ cases \(\d+ %\), \d+ cases/s, (\d+ s|\d+ min \d+ s|\?) left", lines[0]), lines[0]
assert "(100 %)" in lines[-1], lines[-1]
print("progress lines:", len(lines), "last:", lines[-1].strip())

out, status = run(["run", tmp + "/big.json", "-o", tmp + "/q", "--format", "csv", "-q"])
assert "cases/s" not in out, out

# The interrupt: one line saying what was kept (here: the earlier complete run).
out, status = run(["run", tmp + "/big.json", "-o", tmp + "/out", "--format", "csv", "--threads", "1"], interrupt_after=0.5)
assert os.WIFSIGNALED(status) or os.WEXITSTATUS(status) != 0, status
kept = [l for l in out.splitlines() if l.startswith("mhcontact: interrupted:")]
assert len(kept) == 1 and "was left as it was (the previous complete run)" in kept[0], out
out, status = run(["run", tmp + "/big.json", "-o", tmp + "/new", "--format", "csv", "--threads", "1"], interrupt_after=0.5)
assert "mhcontact: interrupted: nothing was kept" in out, out
assert not os.path.exists(tmp + "/new")
# A fleet (batch manifest), plain and --resume: the same line in cases; none with -q or when
# standard error is not a terminal.
fleet = os.path.join(src, "cases", "fleet.json")
for extra in ([], ["--resume"]):
    out, status = run(["run", fleet, "-o", tmp + "/fleet" + "".join(extra), "--threads", "1"] + extra)
    assert os.WEXITSTATUS(status) in (0, 1), (status, out)
    lines = [l for l in re.split(r"[\r\n]", out) if l.startswith("mhcontact run: ") and "cases/s" in l]
    assert lines, out
    assert re.search(r"\d+/396 cases \(\d+ %\), \d+ cases/s, (\d+ s|\d+ min \d+ s|\?) left", lines[0]), lines[0]
    assert "396/396 cases (100 %)" in lines[-1], lines[-1]
    out, status = run(["run", fleet, "-o", tmp + "/fleetq" + "".join(extra), "-q"] + extra)
    assert "cases/s" not in out, out
    p = subprocess.run([bin, "run", fleet, "-o", tmp + "/fleetp" + "".join(extra)] + extra, stderr=subprocess.PIPE, text=True)
    assert "cases/s" not in p.stderr and p.stderr, p.stderr
print("progress_tty: OK")
PY
