#!/usr/bin/python3
"""Plays ur_robot_driver under a namespace for the tests of the real relay (vrrw_demos' replay_real.test,
vrrw_evaluation's test_demo_real.py): the scaled_pos_joint_traj_controller's FollowJointTrajectory action and
joint_states (unprefixed names, all zero at first), as joint_trajectory_controller handles them:

- a goal is executed over its own timing at the driver's rate (~rate, 500 Hz as a UR e-series), with the
  arm's state on joint_states and feedback (desired, actual, error) at 50 Hz; it succeeds at its last point;
- header.stamp zero starts it on receipt; a later stamp waits for it; points whose time has passed at the
  start are skipped; a goal that ended before it arrived is rejected (OLD_HEADER_TIMESTAMP);
- a first point at time 0 farther than ~start_tolerance from the arm is rejected (INVALID_GOAL), as is a
  goal naming other joints (INVALID_JOINTS);
- a new goal preempts the running one (from where the arm is); a cancel stops the arm where it is.

On demand (private parameters, read and cleared when the next goal arrives): ~next_outcome = reject | abort |
error, ~next_error_code (default -1 reject, -4 abort, -5 error) and ~next_abort_at (fraction of the goal's
duration, default 0.5): reject refuses the goal, abort stops the arm there (a protective stop), error runs
it to its end and then reports the code.

Every goal it received is appended to a JSON-lines file with what became of it.

  driver_stand_in.py NS GOALS.jsonl
"""
import bisect
import json
import sys
import threading

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryFeedback,
                              FollowJointTrajectoryResult)
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectoryPoint

JOINTS = ['shoulder_pan_joint', 'shoulder_lift_joint', 'elbow_joint', 'wrist_1_joint', 'wrist_2_joint', 'wrist_3_joint']
Result = FollowJointTrajectoryResult


def hermite(p0, v0, p1, v1, t0, t1, t):
    """Cubic between two points (positions and velocities), as joint_trajectory_controller's spline."""
    h = t1 - t0
    if h <= 0.0:
        return list(p1)
    s = min(max((t - t0) / h, 0.0), 1.0)
    h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
    return [h00 * a + h10 * h * va + h01 * b + h11 * h * vb for a, va, b, vb in zip(p0, v0, p1, v1)]


class Execution:
    """One accepted goal: its points in the driver's joint order, times on the ROS clock."""

    def __init__(self, handle, order, start, now, q):
        points = handle.get_goal().trajectory.points
        self.handle, self.order, self.start = handle, order, start
        self.times = [start.to_sec() + p.time_from_start.to_sec() for p in points]
        self.positions = [[p.positions[k] for k in order] for p in points]
        self.velocities = [[p.velocities[k] for k in order] if p.velocities else [0.0] * len(order) for p in points]
        self.skipped = bisect.bisect_right(self.times, now.to_sec()) if start < now else 0
        # from where the arm is, at the start, to the first point still ahead
        self.times.insert(self.skipped, max(start, now).to_sec())
        self.positions.insert(self.skipped, list(q))
        self.velocities.insert(self.skipped, [0.0] * len(order))
        self.outcome, self.code, self.abort_at = 'succeed', 0, None

    def desired(self, t):
        k = max(self.skipped, bisect.bisect_right(self.times, t) - 1)
        if k + 1 >= len(self.times):
            return self.positions[-1]
        return hermite(self.positions[k], self.velocities[k], self.positions[k + 1], self.velocities[k + 1],
                       self.times[k], self.times[k + 1], t)


class StandInDriver:
    def __init__(self, namespace, record):
        self.record = record
        self.lock = threading.Lock()  # protects state, running and the record file
        self.state = JointState(name=list(JOINTS), position=[0.0] * len(JOINTS), velocity=[0.0] * len(JOINTS))
        self.running = None
        self.start_tolerance = rospy.get_param('~start_tolerance', 0.01)
        self.states = rospy.Publisher(namespace + '/joint_states', JointState, queue_size=10)
        self.server = actionlib.ActionServer(namespace + '/scaled_pos_joint_traj_controller/follow_joint_trajectory',
                                             FollowJointTrajectoryAction, self.on_goal, self.on_cancel, auto_start=False)
        self.server.start()

    def log(self, handle, **fields):
        goal = handle.get_goal()
        points = goal.trajectory.points
        entry = {'joint_names': list(goal.trajectory.joint_names), 'points': len(points),
                 'stamp': goal.trajectory.header.stamp.to_sec(),
                 'first': list(points[0].positions) if points else [], 'last': list(points[-1].positions) if points else [],
                 'seconds': points[-1].time_from_start.to_sec() - points[0].time_from_start.to_sec() if points else 0.0}
        entry.update(fields)
        with open(self.record, 'a') as f:
            f.write(json.dumps(entry) + '\n')

    def reject(self, handle, code, why):
        handle.set_rejected(Result(error_code=code, error_string=why), why)
        self.log(handle, outcome='rejected', error_code=code, error_string=why)

    def on_goal(self, handle):
        outcome = rospy.get_param('~next_outcome', 'succeed')
        code = rospy.get_param('~next_error_code', {'reject': Result.INVALID_GOAL, 'abort': Result.PATH_TOLERANCE_VIOLATED,
                                                    'error': Result.GOAL_TOLERANCE_VIOLATED}.get(outcome, 0))
        abort_at = rospy.get_param('~next_abort_at', 0.5)
        for name in ('~next_outcome', '~next_error_code', '~next_abort_at'):
            if rospy.has_param(name):
                rospy.delete_param(name)
        trajectory = handle.get_goal().trajectory
        if outcome == 'reject':
            return self.reject(handle, code, 'stand-in: rejected on demand')
        if sorted(trajectory.joint_names) != sorted(JOINTS) or not trajectory.points:
            return self.reject(handle, Result.INVALID_JOINTS, 'joints %s are not %s' % (list(trajectory.joint_names), JOINTS))
        order = [list(trajectory.joint_names).index(name) for name in JOINTS]
        now = rospy.Time.now()
        start = now if trajectory.header.stamp.is_zero() else trajectory.header.stamp
        if start + trajectory.points[-1].time_from_start < now:
            return self.reject(handle, Result.OLD_HEADER_TIMESTAMP, 'trajectory ended before it arrived')
        with self.lock:
            first = trajectory.points[0]
            if first.time_from_start.is_zero() and start <= now:
                away = max(abs(first.positions[k] - q) for k, q in zip(order, self.state.position))
                if away > self.start_tolerance:
                    return self.reject(handle, Result.INVALID_GOAL, 'starts %.4f rad from the arm (start tolerance %g)'
                                       % (away, self.start_tolerance))
            if self.running:
                self.finish(GoalStatus.PREEMPTED, Result(error_string='preempted by a new goal'))
            execution = Execution(handle, order, start, now, self.state.position)
            execution.outcome, execution.code = outcome, code
            if outcome == 'abort':
                execution.abort_at = execution.times[execution.skipped] + abort_at * (execution.times[-1] - execution.times[execution.skipped])
            handle.set_accepted()
            self.running = execution

    def on_cancel(self, handle):
        with self.lock:
            if self.running and self.running.handle == handle:
                self.finish(GoalStatus.PREEMPTED, Result(error_string='canceled'))

    def finish(self, status, result):
        """Ends the running goal (lock held); the arm stays where it is."""
        handle, run = self.running.handle, self.running
        self.running = None
        self.state.velocity = [0.0] * len(JOINTS)
        if status == GoalStatus.SUCCEEDED:
            handle.set_succeeded(result, result.error_string)
        elif status == GoalStatus.PREEMPTED:
            handle.set_canceled(result, result.error_string)
        else:
            handle.set_aborted(result, result.error_string)
        self.log(handle, outcome={GoalStatus.SUCCEEDED: 'succeeded', GoalStatus.PREEMPTED: 'canceled'}.get(status, 'aborted'),
                 error_code=result.error_code, error_string=result.error_string, skipped_points=run.skipped,
                 at=list(self.state.position))

    def step(self, now, feedback):
        """One control cycle of the driver."""
        with self.lock:
            run = self.running
            if run:
                t = now.to_sec()
                q = run.desired(t)
                period = 1.0 / rate_hz
                self.state.velocity = [(b - a) / period for a, b in zip(self.state.position, q)]
                self.state.position = q
                if feedback:
                    run.handle.publish_feedback(FollowJointTrajectoryFeedback(
                        joint_names=list(JOINTS), desired=JointTrajectoryPoint(positions=q),
                        actual=JointTrajectoryPoint(positions=q), error=JointTrajectoryPoint(positions=[0.0] * len(q))))
                if run.abort_at is not None and t >= run.abort_at:
                    self.finish(GoalStatus.ABORTED, Result(error_code=run.code, error_string='stand-in: protective stop'))
                elif t >= run.times[-1]:
                    if run.outcome == 'error':
                        self.finish(GoalStatus.ABORTED, Result(error_code=run.code, error_string='stand-in: goal tolerance'))
                    else:
                        self.finish(GoalStatus.SUCCEEDED, Result(error_string='stand-in executed'))
            self.state.header.stamp = now
            self.states.publish(self.state)


def main():
    global rate_hz
    rospy.init_node('stand_in_driver')
    namespace, record = rospy.myargv(sys.argv)[1].rstrip('/'), rospy.myargv(sys.argv)[2]
    rate_hz = rospy.get_param('~rate', 500.0)
    driver = StandInDriver(namespace, record)
    rate = rospy.Rate(rate_hz)
    cycle = 0
    while not rospy.is_shutdown():
        driver.step(rospy.Time.now(), feedback=cycle % max(1, int(rate_hz / 50)) == 0)
        cycle += 1
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


rate_hz = 500.0

if __name__ == '__main__':
    main()
