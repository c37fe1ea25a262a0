#!/usr/bin/python3
"""Stand-in for the physics node in tests: each joint is a stiff second-order drive toward its
target (q'' = K (q* - q) + D (qd* - qd)) from an initial pose, an optional constant sag per joint,
and optional upper stops per joint (objects in the way). Subscribes drive_targets, publishes joint_states."""
import rospy
from sensor_msgs.msg import JointState


def main():
    rospy.init_node("physics_stand_in")
    joints = rospy.get_param("~joints")
    stiffness, damping = rospy.get_param("~stiffness", 900.0), rospy.get_param("~damping", 60.0)
    sag = rospy.get_param("~sag", {})
    block = rospy.get_param("~block", {})
    rate_hz = rospy.get_param("~rate", 250.0)
    initial = rospy.get_param("~initial", {})
    q = {j: initial.get(j, 0.0) for j in joints}
    v = {j: 0.0 for j in joints}
    target = {j: (q[j], 0.0) for j in joints}

    def on_targets(msg):
        for i, name in enumerate(msg.name):
            if name in target:
                target[name] = (msg.position[i], msg.velocity[i] if i < len(msg.velocity) else 0.0)

    rospy.Subscriber("drive_targets", JointState, on_targets, queue_size=10, tcp_nodelay=True)
    pub = rospy.Publisher("joint_states", JointState, queue_size=10)
    dt = 1.0 / rate_hz
    rate = rospy.Rate(rate_hz)
    while not rospy.is_shutdown():
        effort = []
        for j in joints:
            qt, vt = target[j]
            qt -= sag.get(j, 0.0)
            a = stiffness * (qt - q[j]) + damping * (vt - v[j])
            v[j] += a * dt
            q[j] += v[j] * dt
            if j in block and q[j] > block[j]:
                q[j], v[j] = block[j], 0.0
            effort.append(stiffness * (qt - q[j]) * 0.01)
        pub.publish(JointState(header=rospy.Header(stamp=rospy.Time.now()), name=joints,
                               position=[q[j] for j in joints], velocity=[v[j] for j in joints], effort=effort))
        rate.sleep()


if __name__ == "__main__":
    main()
