"""Runs vplant with a bus served over socketcand for the python-can integration tests.

`served_plant(vplant, scenario, extra_args)` starts `vplant run SCENARIO --no-script --realtime
--can main=socketcand:127.0.0.1:PORT` on a free port in a temporary directory, yields
(process, port, reader) once the bus is served, and stops the run (SIGINT) afterwards.
"""
import contextlib
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time


class Failure(Exception):
    pass


class StderrReader(threading.Thread):
    def __init__(self, stream):
        super().__init__(daemon=True)
        self.stream, self.lines, self.served = stream, [], threading.Event()

    def run(self):
        for line in self.stream:
            self.lines.append(line)
            if "socketcand: bus 'main' served on" in line:
                self.served.set()


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def check(condition, text):
    if not condition:
        raise Failure(text)
    print("ok:", text, flush=True)


def stop(proc, reader):
    """SIGINT, then the run's output; Failure if it does not exit cleanly."""
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=15)
    reader.join(5)
    sys.stderr.write("".join(reader.lines))
    if proc.returncode != 0:
        raise Failure(f"vplant exited with {proc.returncode}:\n{out}")
    print(out, end="")


@contextlib.contextmanager
def served_plant(vplant, scenario, extra_args=()):
    workdir = tempfile.mkdtemp(prefix="vplant-socketcand-")  # the scenario's outputs land here
    proc = reader = None
    try:
        for _ in range(3):  # the free port may be taken between the probe and vplant's bind
            port = free_port()
            proc = subprocess.Popen([vplant, "run", scenario, "--no-script", "--realtime", "--duration", "40",
                                     "--can", f"main=socketcand:127.0.0.1:{port}", *extra_args],
                                    cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            reader = StderrReader(proc.stderr)
            reader.start()
            deadline = time.monotonic() + 20
            while not reader.served.wait(0.1) and proc.poll() is None and time.monotonic() < deadline:
                pass
            if reader.served.is_set():
                break
            proc.kill()
            proc.wait()
            sys.stderr.write("".join(reader.lines))
            proc = None
        if proc is None:
            raise Failure("vplant did not serve the bus")
        yield proc, port, reader
    except Failure:
        if proc is not None and proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait(10)
            reader.join(5)
            sys.stderr.write("".join(reader.lines))
        raise
    finally:
        if proc is not None and proc.poll() is None:
            proc.kill()
            proc.wait()
        shutil.rmtree(workdir, ignore_errors=True)
