#!/usr/bin/python3
"""A teacher from outside the workspace: teaches a pick-and-place of one object by the operator's interfaces only
(the ghost services, free-drive with a tracked hand, GripperCommand), records it with /demos/start and /demos/stop,
and writes where its own actions were (the truth the segmentation is checked against). No annotation is made.

  scripted_teacher.py --object NAME --grasp X,Y,Z --place DX,DY --truth OUT.json [--bag OUT.bag]
                      [--robot ur5e] [--pace brisk|hesitant] [--descent ghost|hand] [--effort N] [--close POS]

--bag: record through /demos/start and /demos/stop; without it a recorder already records (./vrrw record).

--grasp: the TCP at the grasp in the object's frame (taken from above, fingers across the object's y);
--place: where the object is set down, from where it stood (m, world x and y). A hesitant teacher pauses as a
person does: before each action, halfway down to the grasp, halfway up, 10 s after the lift, above the place.
"""
import argparse
import json
import math
import sys
import time

import actionlib
import rospy
import tf2_ros
from control_msgs.msg import GripperCommand, GripperCommandAction, GripperCommandGoal
from geometry_msgs.msg import PoseStamped
from std_msgs.msg import Float64
from std_srvs.srv import SetBool, Trigger
from vrrw_msgs.msg import Event
from vrrw_msgs.srv import DemoStart, DemoStop, GhostExecute, GhostPlan, GhostSetPose, GhostSupportSurface


def quaternion_multiply(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def rotate(q, v):
    x, y, z, _ = quaternion_multiply(quaternion_multiply(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


class Teacher:
    def __init__(self, args):
        self.args = args
        self.ns = '/' + args.robot + '/'
        self.truth = []
        self.services = {}
        self.tf = tf2_ros.Buffer()
        self.listener = tf2_ros.TransformListener(self.tf)
        self.gripper = actionlib.SimpleActionClient(self.ns + 'gripper_controller/gripper_cmd', GripperCommandAction)
        self.hand_pose = rospy.Publisher('/operator/right/pose', PoseStamped, queue_size=10)
        self.hand_grip = rospy.Publisher('/operator/right/grip', Float64, queue_size=10)
        self.events = []
        rospy.Subscriber('/operator/events', Event, self.on_event)

    def call(self, name, kind, *request, check=True):
        if name not in self.services:
            rospy.wait_for_service(name, 30.0)
            self.services[name] = rospy.ServiceProxy(name, kind, persistent=True)
        answer = self.services[name](*request)
        if check and hasattr(answer, 'success') and not answer.success:
            sys.exit(f'scripted_teacher: {name}: {answer.message}')
        return answer

    def pause(self, seconds):
        if self.args.pace == 'hesitant':
            rospy.sleep(seconds)  # simulated time: a person's pause is time in the cell
        else:
            rospy.sleep(0.3)

    def frame(self, name):
        t = self.tf.lookup_transform('world', name, rospy.Time(0), rospy.Duration(10.0)).transform
        return (t.translation.x, t.translation.y, t.translation.z), (t.rotation.x, t.rotation.y, t.rotation.z,
                                                                    t.rotation.w)

    def ghost_to(self, position, orientation, action, waypoints=(), surface=''):
        self.call(self.ns + 'ghost/clear_waypoints', Trigger)
        self.call(self.ns + 'ghost/set_support_surface', GhostSupportSurface, surface)
        for point in waypoints:
            self.call(self.ns + 'ghost/set_pose', GhostSetPose, self.pose(point, orientation))
            self.call(self.ns + 'ghost/add_waypoint', Trigger)
        self.call(self.ns + 'ghost/set_pose', GhostSetPose, self.pose(position, orientation))
        self.call(self.ns + 'ghost/plan', GhostPlan, 1.0, 0.0, 0.2, 'minimum_jerk')
        start = rospy.Time.now().to_sec()
        self.execute()
        self.truth.append({'action': action, 'start': start, 'end': rospy.Time.now().to_sec()})

    def execute(self):
        """The ghost's plan; a person clicks once more when the arm stopped just outside the goal tolerance (a
        loaded machine lets the drives trail): the second plan moves it the last millimetres."""
        answer = self.call(self.ns + 'ghost/execute', GhostExecute, check=False)
        if not answer.success and 'goal tolerance' in answer.message:
            print(f'scripted_teacher: {answer.message}: again', flush=True)
            self.call(self.ns + 'ghost/plan', GhostPlan, 1.0, 0.0, 0.2, 'minimum_jerk')
            answer = self.call(self.ns + 'ghost/execute', GhostExecute)
        elif not answer.success:
            sys.exit(f'scripted_teacher: {self.ns}ghost/execute: {answer.message}')

    def pose(self, position, orientation):
        message = PoseStamped()
        message.header.frame_id = 'world'
        message.pose.position.x, message.pose.position.y, message.pose.position.z = position
        (message.pose.orientation.x, message.pose.orientation.y, message.pose.orientation.z,
         message.pose.orientation.w) = orientation
        return message

    def grip(self, position, effort, action):
        self.gripper.wait_for_server(rospy.Duration(30.0))
        start = rospy.Time.now().to_sec()
        self.gripper.send_goal_and_wait(GripperCommandGoal(command=GripperCommand(position=position, max_effort=effort)))
        self.truth.append({'action': action, 'start': start, 'end': rospy.Time.now().to_sec()})

    def on_event(self, event):
        if event.detail.startswith('hand right '):
            self.events.append(event.kind)

    def hold_hand(self, point, orientation, grip, kind, seconds):
        """Holds the hand at point (publishing at a tracker's 100 Hz) until the interaction node reports kind."""
        self.events = []
        end = time.monotonic() + seconds
        while time.monotonic() < end and kind not in self.events:
            message = self.pose(point, orientation)
            message.header.stamp = rospy.Time.now()
            self.hand_pose.publish(message)
            self.hand_grip.publish(Float64(grip))
            time.sleep(0.01)
        if kind and kind not in self.events:
            sys.exit(f'scripted_teacher: the interaction node did not report {kind} of the hand within {seconds} s')

    def hand_down(self, start, end, orientation, seconds, action):
        """Free-drive: the hand closes on the wrist at the flange, pulls it down (minimum jerk), lets go."""
        self.call(self.ns + 'free_drive', SetBool, True)
        flange, _ = self.frame(self.args.robot + '_flange')
        tcp, _ = self.frame(self.args.robot + '_tcp')
        grab = tuple(f - t for f, t in zip(flange, tcp))
        at = lambda point: tuple(p + g for p, g in zip(point, grab))  # noqa: E731
        self.hold_hand(at(start), orientation, 1.0, 'grab', 10.0)
        # the action is the pull: a grab moves nothing (the spring takes the wrist where it is), and how long the
        # interaction node takes to report it is the machine's load (0.2-0.4 s measured), not the teacher's doing
        t0 = rospy.Time.now().to_sec()
        steps = int(seconds * 100)
        for k in range(steps + 1):
            s = k / steps
            s = s * s * s * (10 - 15 * s + 6 * s * s)
            message = self.pose(at(tuple(a + s * (b - a) for a, b in zip(start, end))), orientation)
            message.header.stamp = rospy.Time.now()
            self.hand_pose.publish(message)
            self.hand_grip.publish(Float64(1.0))
            time.sleep(0.01)  # a tracker's rate is its own
        self.hold_hand(at(end), orientation, 1.0, '', 0.3)
        self.hold_hand(at(end), orientation, 0.0, 'release', 10.0)
        self.call(self.ns + 'free_drive', SetBool, False)
        self.truth.append({'action': action, 'start': t0, 'end': rospy.Time.now().to_sec()})

    def teach(self):
        args = self.args
        grasp_in_object = [float(v) for v in args.grasp.split(',')]
        place = [float(v) for v in args.place.split(',')]
        position, orientation = self.frame(args.object)
        yaw = 2.0 * math.atan2(orientation[2], orientation[3])
        down = quaternion_multiply((0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)), (1.0, 0.0, 0.0, 0.0))
        offset = rotate(orientation, grasp_in_object)
        grasp = tuple(p + o for p, o in zip(position, offset))
        above = (grasp[0], grasp[1], grasp[2] + 0.12)
        halfway = (grasp[0], grasp[1], grasp[2] + 0.06)
        tcp, _ = self.frame(args.robot + '_tcp')
        high = ((tcp[0] + above[0]) / 2, (tcp[1] + above[1]) / 2, max(tcp[2], above[2]))
        place_at = (grasp[0] + place[0], grasp[1] + place[1], grasp[2] - 0.002)  # pressed 2 mm onto the table
        above_place = (place_at[0], place_at[1], above[2])
        if args.bag:
            self.call('/demos/start', DemoStart, args.bag, [args.robot])
        self.call(self.ns + 'ghost/reset', Trigger)
        self.pause(3.0)
        self.ghost_to(high, down, 'near_pick')
        self.pause(4.0)
        self.ghost_to(above, down, 'near_pick')
        self.pause(2.5)
        if args.descent == 'hand':
            self.hand_down(above, grasp, down, 1.5 if args.pace == 'brisk' else 3.0, 'pick')
        else:
            if args.pace == 'hesitant':
                self.ghost_to(halfway, down, 'pick')
                self.pause(1.5)
            self.ghost_to(grasp, down, 'pick')
        self.pause(3.0)
        self.grip(args.close, args.effort, 'close_gripper')
        self.pause(2.0)
        if args.pace == 'hesitant':
            self.ghost_to(halfway, down, 'back_to_near_pick')
            self.pause(1.0)
        self.ghost_to(above, down, 'back_to_near_pick')
        self.pause(10.0)
        self.ghost_to(above_place, down, 'final')
        self.pause(2.0)
        self.ghost_to(place_at, down, 'final', surface='table')
        self.pause(2.0)
        self.grip(0.0, 0.0, 'open_gripper')
        self.pause(1.0)
        if args.bag:
            self.call('/demos/stop', DemoStop)
        with open(args.truth, 'w') as f:
            json.dump({'actions': self.truth, 'grasp_in_object': grasp_in_object, 'object': args.object}, f, indent=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--object', required=True)
    parser.add_argument('--grasp', required=True)
    parser.add_argument('--place', required=True)
    parser.add_argument('--bag', default='')
    parser.add_argument('--truth', required=True)
    parser.add_argument('--robot', default='ur5e')
    parser.add_argument('--pace', choices=('brisk', 'hesitant'), default='brisk')
    parser.add_argument('--descent', choices=('ghost', 'hand'), default='ghost')
    parser.add_argument('--effort', type=float, default=70.0)
    parser.add_argument('--close', type=float, default=0.8)
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('scripted_teacher', anonymous=True)
    Teacher(args).teach()


if __name__ == '__main__':
    main()
