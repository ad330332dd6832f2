#!/usr/bin/python3
"""The launch file as docs/ros.md runs it (ctest label `ros`): roslaunch aco_planner office.launch
on a free port, then the page's `rosservice call /make_plan ...`, whose answer must be a plan;
roslaunch is stopped as Ctrl-C stops it, and with it every process it started.

    tests/ros/ros_launch_test.py BUILD_DIR"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools/ros"))
from ros_session import free_port  # noqa: E402

BUILD = Path(sys.argv[1]).resolve()
DOC = Path(__file__).resolve().parents[2] / "docs/ros.md"


def documented_call() -> str:
    """The page's rosservice line, as written (a block of two lines)."""
    text = DOC.read_text()
    match = re.search(r'rosservice call /make_plan "(.*?)"', text, re.S)
    if not match:
        raise SystemExit(f"{DOC}: no rosservice call /make_plan line")
    return match.group(1)


def main(scratch: Path) -> None:
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOME=str(scratch), ROS_LOG_DIR=str(scratch),
               ROS_PACKAGE_PATH=str(BUILD / "ros"))
    log = (scratch / "launch.log").open("w")
    launch = subprocess.Popen(["roslaunch", "-p", str(port), "aco_planner", "office.launch"], env=env, stdout=log,
                              stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.time() + 60
        while True:
            listed = subprocess.run(["rosservice", "list"], env=env, capture_output=True, text=True)
            if "/make_plan" in listed.stdout.split():
                break
            if time.time() > deadline or launch.poll() is not None:
                raise SystemExit(f"no /make_plan within 60 s:\n{(scratch / 'launch.log').read_text()[-3000:]}")
            time.sleep(0.5)
        time.sleep(1.0)  # the latched map reaches the node
        answer = subprocess.run(["rosservice", "call", "/make_plan", documented_call()], env=env, capture_output=True,
                                text=True, timeout=60)
        poses = answer.stdout.count("position:")
        if answer.returncode != 0 or poses < 2:
            raise SystemExit(f"rosservice call /make_plan: exit {answer.returncode}, {poses} poses:\n{answer.stdout}"
                             f"{answer.stderr}\n{(scratch / 'launch.log').read_text()[-3000:]}")
        print(f"ok: the launch file serves a plan of {poses} poses to the documented rosservice call")
    finally:
        launch.send_signal(signal.SIGINT)  # as Ctrl-C: roslaunch ends its nodes and its master
        try:
            launch.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(launch.pid, signal.SIGKILL)
            launch.wait()
    time.sleep(0.5)
    try:
        os.killpg(launch.pid, 0)
        left = subprocess.run(["ps", "-o", "pid,args", "-g", str(launch.pid)], capture_output=True, text=True).stdout
        os.killpg(launch.pid, signal.SIGKILL)
        raise SystemExit(f"processes of the launch left running:\n{left}")
    except ProcessLookupError:
        print("ok: roslaunch ended every process it started")


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as scratch:
        main(Path(scratch))
