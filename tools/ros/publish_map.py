#!/usr/bin/python3
"""Publishes a ROS map_server map (YAML + PGM) on the `map` topic, latched, as map_server does:
the map for aco-ros-planner's launch file and its test, where Debian ships no map_server.

    tools/ros/publish_map.py data/maps/ros/office.yaml [--frame map] [__name:=map_publisher]

The YAML's resolution and origin place the map; its mode (trinary, the default, or scale),
negate, occupied_thresh and free_thresh turn grey levels into occupancies as map_server does."""
import argparse
import math
import sys
from pathlib import Path

import rospy
import yaml
from nav_msgs.msg import OccupancyGrid


def read_pgm(path: Path):
    """A binary (P5) or text (P2) PGM: width, height, maximum and the grey levels, top row first."""
    data = path.read_bytes()
    words, at = [], 0
    while len(words) < 4:  # magic, width, height, maximum; comments start with #
        while data[at:at + 1].isspace():
            at += 1
        if data[at:at + 1] == b"#":
            at = data.index(b"\n", at) + 1
            continue
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        words.append(data[at:end].decode())
        at = end
    magic, width, height, maximum = words[0], int(words[1]), int(words[2]), int(words[3])
    if magic == "P5":
        pixels = list(data[at + 1:at + 1 + width * height])
    elif magic == "P2":
        pixels = [int(word) for word in data[at:].split()]
    else:
        raise SystemExit(f"{path}: not a PGM (magic {magic})")
    if len(pixels) != width * height:
        raise SystemExit(f"{path}: {len(pixels)} pixels for {width}x{height}")
    return width, height, maximum, pixels


def occupancy_grid(yaml_file: Path, frame: str) -> OccupancyGrid:
    meta = yaml.safe_load(yaml_file.read_text())
    width, height, maximum, pixels = read_pgm(yaml_file.parent / meta["image"])
    negate = int(meta.get("negate", 0))
    occupied, free = float(meta.get("occupied_thresh", 0.65)), float(meta.get("free_thresh", 0.196))
    mode = meta.get("mode", "trinary")
    grid = OccupancyGrid()
    grid.header.frame_id = frame
    grid.info.resolution = float(meta["resolution"])
    grid.info.width, grid.info.height = width, height
    x, y, yaw = (float(v) for v in meta["origin"])
    grid.info.origin.position.x, grid.info.origin.position.y = x, y
    grid.info.origin.orientation.z, grid.info.origin.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    data = []
    for row in range(height - 1, -1, -1):  # the grid's first row is the image's last
        for column in range(width):
            grey = pixels[row * width + column]
            p = grey / maximum if negate else (maximum - grey) / maximum
            if p > occupied:
                data.append(100)
            elif p < free:
                data.append(0)
            elif mode == "scale":
                data.append(int(round(99 * (p - free) / (occupied - free))))
            else:
                data.append(-1)
    grid.data = data
    return grid


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("yaml", type=Path)
    parser.add_argument("--frame", default="map")
    args = parser.parse_args(rospy.myargv(sys.argv)[1:])
    rospy.init_node("map_publisher")
    grid = occupancy_grid(args.yaml, args.frame)
    publisher = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    grid.header.stamp = rospy.Time.now()
    publisher.publish(grid)
    rospy.loginfo("published %s: %dx%d at %g m", args.yaml, grid.info.width, grid.info.height, grid.info.resolution)
    rospy.spin()


if __name__ == "__main__":
    main()
