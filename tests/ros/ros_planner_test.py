#!/usr/bin/python3
"""aco-ros-planner against a real ROS master (ctest label `ros`): Debian's rosmaster on a free
port, the bundled office map published with rospy, the node, and make_plan called as move_base
would call it (tools/ros/ros_session.py).

    tests/ros/ros_planner_test.py BUILD_DIR

Checks: every path is collision-free, from start to goal, and as long as acoplan's on the same map
with the same keys and seed; impossible requests (no map yet, outside the map, in a wall, another
frame, unreachable, a bad parameter) give an empty plan and a ROS error naming the reason, and the
node keeps serving; a parameter set between two calls changes the next plan; every process this
test starts is ended."""
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools/ros"))
from publish_map import occupancy_grid  # noqa: E402
from ros_session import NODE, RosSession, cell_centre  # noqa: E402

BUILD = Path(sys.argv[1]).resolve()
OFFICE = ROOT / "data/maps/ros/office.yaml"
KEYS = {"ants": 20, "iterations": 20, "seed": 3}  # a small colony, as acoplan runs it below
NODE_DEFAULTS = {"smoother.clearance": 0.25}  # the node's own default (hosts/ros_planner/README.md)


def check(condition, what):
    if not condition:
        raise AssertionError(what)
    print("ok:", what, flush=True)


def test(ros: RosSession):
    import rospy
    from nav_msgs.msg import OccupancyGrid, Path as PathMessage

    ros.start_node(KEYS)
    office = occupancy_grid(OFFICE, "map")
    info = office.info

    def centre(cell):
        return cell_centre(info, cell)

    def call(start_cell, goal_cell, tolerance=0.0, frame="map"):
        return ros.make_plan(centre(start_cell), centre(goal_cell), tolerance, frame)

    plan, said = call((8, 8), (90, 60))
    check(not plan.poses and "no map yet" in said, "before any map: an empty plan, and the error says no map yet")
    ros.publish(office, "aco planner: map 100x70")

    blocked = {(x, info.height - 1 - row) for row in range(info.height) for x in range(info.width)
               if office.data[row * info.width + x] != 0}

    def free_segment(a, b):  # sampled at an eighth of a cell
        steps = int(math.ceil(max(abs(b[0] - a[0]), abs(b[1] - a[1])) / (info.resolution / 8))) + 1
        for i in range(steps + 1):
            x, y = a[0] + (b[0] - a[0]) * i / steps, a[1] + (b[1] - a[1]) * i / steps
            column = math.floor((x - info.origin.position.x) / info.resolution)
            row = info.height - 1 - math.floor((y - info.origin.position.y) / info.resolution)
            if (column, row) in blocked:
                return False
        return True

    def acoplan(start_cell, goal_cell):
        words = [BUILD / "bin/acoplan", "--map", OFFICE, "--start", "%d,%d" % start_cell, "--goal", "%d,%d" % goal_cell,
                 "--json"] + [f"--{k}={v}" for k, v in {**KEYS, **NODE_DEFAULTS}.items()]
        return json.loads(subprocess.run([str(w) for w in words], capture_output=True, text=True, check=True).stdout)

    for start_cell, goal_cell in [((8, 8), (90, 60)), ((90, 60), (8, 8)), ((30, 8), (80, 25)), ((50, 35), (10, 60))]:
        plan, said = call(start_cell, goal_cell)
        points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
        what = f"{start_cell} -> {goal_cell}"
        check(len(points) >= 2 and "ERROR" not in said, f"{what}: a plan")
        check(plan.header.frame_id == "map" and all(p.header.frame_id == "map" for p in plan.poses),
              f"{what}: in the map's frame")
        # Within a micrometre: the map's resolution travels as a 32-bit float.
        check(math.dist(points[0], centre(start_cell)) < 1e-6 and math.dist(points[-1], centre(goal_cell)) < 1e-6,
              f"{what}: from the start's cell to the goal's ({points[0]} -> {points[-1]})")
        check(all(free_segment(a, b) for a, b in zip(points, points[1:])), f"{what}: collision-free")
        length = sum(math.dist(a, b) for a, b in zip(points, points[1:])) / info.resolution
        expected = acoplan(start_cell, goal_cell)["length"]
        check(abs(length - expected) < 1e-6 * expected, f"{what}: {length:.4f} cells, as acoplan's {expected:.4f}")
        facing = [2 * math.atan2(p.pose.orientation.z, p.pose.orientation.w) for p in plan.poses[:-1]]
        headings = [math.atan2(b[1] - a[1], b[0] - a[0]) for a, b in zip(points, points[1:])]
        check(all(abs(math.remainder(f - h, 2 * math.pi)) < 1e-9 for f, h in zip(facing, headings)),
              f"{what}: each pose faces the next")

    # Impossible requests: an empty plan, a ROS error with the reason, and the node lives on.
    for goal_cell, frame, reason in [((200, 10), "map", "is outside the map"),
                                     ((0, 0), "map", "occupied or unknown cell"),
                                     ((8, 8), "odom", "the map in 'map'")]:
        plan, said = call((8, 8), goal_cell, 0.0, frame)
        check(not plan.poses and reason in said, f"goal {goal_cell} in frame {frame}: empty plan, error '{reason}'")
    # Tolerance: a goal in a wall moves to the nearest free cell within it.
    wall = next(c for c in sorted(blocked, key=lambda c: (c[1], c[0])) if c[1] == 8 and c[0] > 8)
    plan, said = call((8, 8), wall, tolerance=0.25)
    end = (plan.poses[-1].pose.position.x, plan.poses[-1].pose.position.y) if plan.poses else None
    check(end and math.dist(end, centre(wall)) <= 0.25 + 1e-6, f"goal in the wall {wall}, tolerance 0.25 m: planned")
    # Bad parameters are named as the user set them.
    for name, value, what in [("update/rhoo", 0.5, "an unknown parameter"), ("time_limit", -1.0, "a bad value")]:
        rospy.set_param(f"{NODE}/{name}", value)
        plan, said = call((8, 8), (90, 60))
        check(not plan.poses and f"~{name}" in said, f"{what}: empty plan, the error names ~{name}")
        rospy.delete_param(f"{NODE}/{name}")
    # The node's own parameters: unknown cells free, the occupancy threshold, the pheromone.
    rospy.set_param(f"{NODE}/allow_unknown", True)
    plan, said = call((8, 8), (0, 0))
    check(not plan.poses and "not reachable" in said, "~allow_unknown: a goal in unknown space is free (and walled off)")
    rospy.delete_param(f"{NODE}/allow_unknown")
    rospy.set_param(f"{NODE}/occupied_threshold", 0)
    plan, said = call((8, 8), (90, 60))
    check(not plan.poses and "the start" in said and "occupied" in said, "~occupied_threshold 0: every cell is occupied")
    rospy.delete_param(f"{NODE}/occupied_threshold")
    rospy.set_param(f"{NODE}/publish_pheromone", True)
    plan, said = call((8, 8), (90, 60))
    field = rospy.wait_for_message("pheromone", OccupancyGrid, timeout=10)
    check(field.info.width == info.width and len(field.data) == len(office.data) and max(field.data) == 100
          and min(field.data) >= 0, "~publish_pheromone: the field on the map's cells, scaled to 0-100")
    rospy.delete_param(f"{NODE}/publish_pheromone")
    # A parameter changed between calls changes the next plan: no smoother, every grid step a pose.
    pruned, _ = call((8, 8), (90, 60))
    rospy.set_param(f"{NODE}/smoother", "none")
    raw, _ = call((8, 8), (90, 60))
    check(len(raw.poses) > len(pruned.poses), f"~smoother none: {len(raw.poses)} poses, not {len(pruned.poses)}")
    rospy.delete_param(f"{NODE}/smoother")
    # A new map replaces the old one: a wall across the office cuts the goal off.
    walled = occupancy_grid(OFFICE, "map")
    walled.data = [100 if i % info.width == 50 else v for i, v in enumerate(walled.data)]
    walled.info.width = info.width  # the same size: the log line alone does not tell the maps apart
    ros.publish(walled, "aco planner: map 100x70")
    plan, said = call((8, 8), (90, 60))
    check(not plan.poses and "not reachable" in said, "a new map with a wall: empty plan, the goal is not reachable")
    ros.publish(office, "aco planner: map 100x70")
    plan, said = call((8, 8), (90, 60))
    check(plan.poses, "the office again: the node still serves")
    last = rospy.wait_for_message("plan", PathMessage, timeout=10)
    check(len(last.poses) == len(plan.poses), "the plan topic carries the last plan")


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as scratch:
        with RosSession(Path(scratch), BUILD) as ros:
            try:
                test(ros)
            except BaseException:
                for log in Path(scratch).glob("*.log"):
                    print(f"--- {log.name}\n{log.read_text()[-3000:]}", file=sys.stderr)
                raise
        left = ros.left_running()
        check(not left, "every process the test started has ended")
