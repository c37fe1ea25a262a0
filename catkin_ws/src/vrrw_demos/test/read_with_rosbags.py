#!/usr/bin/env python3
"""Reads a demonstration bag with the independent `rosbags` package (not ROS's rosbag): prints
`TOPIC COUNT` per topic and `last r1 position[0] VALUE` from the last /r1/joint_states message."""
import sys

from rosbags.rosbag1 import Reader
from rosbags.typesys import Stores, get_typestore


def main(path):
    typestore = get_typestore(Stores.ROS1_NOETIC)
    counts, last = {}, None
    with Reader(path) as reader:
        for connection, _, raw in reader.messages():
            counts[connection.topic] = counts.get(connection.topic, 0) + 1
            if connection.topic == "/r1/joint_states":
                last = typestore.deserialize_ros1(raw, connection.msgtype)
    for topic in sorted(counts):
        print(topic, counts[topic])
    if last is not None:
        print("last r1 position[0]", last.position[0])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
