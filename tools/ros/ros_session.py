"""A ROS 1 session of its own for aco-ros-planner's test and figures: Debian's rosmaster on a free
port, the node, and rospy in this process, every process ended on leaving.

    with RosSession(scratch, build) as ros:
        ros.start_node({"ants": 20})
        ros.publish(occupancy_grid(...))
        plan = ros.make_plan(start, goal)
"""
import os
import socket
import subprocess
import time
from pathlib import Path

NODE = "/aco_planner"


def cell_centre(info, cell):
    """The centre of aco's cell (x, row from the top) in the frame of a map with nav_msgs' `info`."""
    return (info.origin.position.x + (cell[0] + 0.5) * info.resolution,
            info.origin.position.y + (info.height - 1 - cell[1] + 0.5) * info.resolution)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class RosSession:
    def __init__(self, scratch: Path, build: Path):
        self.scratch, self.build = Path(scratch), Path(build)
        self.processes = []
        self.node_log = self.scratch / "node.log"

    def __enter__(self):
        port = free_port()
        os.environ.update(ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_HOME=str(self.scratch),
                          ROS_LOG_DIR=str(self.scratch), ROSCONSOLE_STDOUT_LINE_BUFFERED="1", PYTHONUNBUFFERED="1")
        self.start(["rosmaster", "--core", "-p", port], "master.log")
        import rosgraph
        deadline = time.time() + 30
        while not rosgraph.is_master_online():
            if time.time() > deadline:
                raise RuntimeError("rosmaster did not answer within 30 s")
            time.sleep(0.2)
        import rospy
        from nav_msgs.msg import OccupancyGrid
        rospy.init_node("aco_planner_client", disable_signals=True)
        self.publisher = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
        return self

    def __exit__(self, *failure):
        for process in reversed(self.processes):
            if process.poll() is None:
                process.terminate()
        for process in self.processes:
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        return False

    def start(self, words, log: str):
        process = subprocess.Popen([str(w) for w in words], stdout=(self.scratch / log).open("w"),
                                   stderr=subprocess.STDOUT, env=os.environ)
        self.processes.append(process)
        return process

    def left_running(self):
        return [p.args for p in self.processes if p.poll() is None]

    def start_node(self, parameters: dict):
        """The node, with private parameters set before it starts."""
        import rospy
        from nav_msgs.srv import GetPlan
        for key, value in parameters.items():
            rospy.set_param(f"{NODE}/{key}", value)
        self.start([self.build / "bin/aco-ros-planner", f"__name:={NODE[1:]}"], "node.log")
        rospy.wait_for_service("make_plan", timeout=30)
        self.service = rospy.ServiceProxy("make_plan", GetPlan, persistent=True)

    def log(self) -> str:
        return self.node_log.read_text()

    def publish(self, grid, wait_for: str = ""):
        """Publishes a map; waits until the node's log says WAIT_FOR (its "map WxH" line)."""
        mark = len(self.log())
        self.publisher.publish(grid)
        deadline = time.time() + 20
        while wait_for and wait_for not in self.log()[mark:]:
            if time.time() > deadline:
                raise RuntimeError(f"the node did not log '{wait_for}' within 20 s")
            time.sleep(0.05)

    def make_plan(self, start, goal, tolerance=0.0, frame="map"):
        """The plan between two points (x, y) in metres, and the node's log lines meanwhile."""
        from geometry_msgs.msg import PoseStamped
        poses = []
        for x, y in (start, goal):
            pose = PoseStamped()
            pose.header.frame_id = frame
            pose.pose.position.x, pose.pose.position.y = x, y
            pose.pose.orientation.w = 1.0
            poses.append(pose)
        mark = len(self.log())
        plan = self.service(poses[0], poses[1], tolerance).plan
        said = ""
        deadline = time.time() + 5
        while "aco planner: " not in said and time.time() < deadline:  # the node's line for this request
            time.sleep(0.02)
            said = self.log()[mark:]
        return plan, said
