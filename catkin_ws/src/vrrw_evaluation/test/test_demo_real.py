"""./vrrw demo --real NS as a user runs it against a robot's master: a stand-in for ur_robot_driver under NS
gets the demonstration's arm instructions only through vrrw's real relay, unchanged but for the joint names'
prefix; bad --real input stops with one line before any stage runs."""
import json
import os
import socket
import subprocess
import sys
import tempfile
import time
import unittest

import rosgraph

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(HERE, '../../../..')))
VRRW = os.path.join(ROOT, 'vrrw')
ACTION = '/stand_in/scaled_pos_joint_traj_controller/follow_joint_trajectory'
JOINTS = ['shoulder_pan_joint', 'shoulder_lift_joint', 'elbow_joint', 'wrist_1_joint', 'wrist_2_joint', 'wrist_3_joint']
ARM = ['to_the_recorded_start', 'move_to_near_pick', 'move_to_pick', 'back_to_near_pick', 'move_to_final']


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def demo(*args, env, timeout):
    return subprocess.run([VRRW, 'demo', *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=timeout, env=env)


class RealRelayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        port = free_port()
        cls.env = dict(os.environ, ROS_MASTER_URI=f'http://127.0.0.1:{port}')
        cls.processes = [subprocess.Popen(['rosmaster', '--core', '-p', str(port)], env=cls.env,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
        cls.goals = os.path.join(tempfile.mkdtemp(prefix='vrrw_stand_in_'), 'goals.jsonl')
        cls.processes.append(subprocess.Popen([sys.executable, os.path.join(ROOT, 'catkin_ws/src/vrrw_control/test/driver_stand_in.py'),
                                               '/stand_in', cls.goals], env=cls.env))
        master = rosgraph.Master('/test_demo_real', master_uri=cls.env['ROS_MASTER_URI'])
        for _ in range(300):
            try:
                if ACTION + '/status' in {name for name, _ in master.getPublishedTopics('')}:
                    break
            except OSError:
                pass
            time.sleep(0.1)
        cls.out = tempfile.mkdtemp(prefix='vrrw_demo_real_')
        cls.result = demo('--trials', '0', '--seed', '3', '--real', '/stand_in', '--yes', '--out', cls.out,
                          env=cls.env, timeout=300)
        print(cls.result.stdout[-3000:])

    @classmethod
    def tearDownClass(cls):
        for process in reversed(cls.processes):
            process.terminate()
            process.wait(timeout=10)

    def test_every_instruction_went_through_the_relay(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr[-2000:])
        with open(os.path.join(self.out, 'relay.json')) as f:
            relay = json.load(f)
        self.assertEqual(relay['driver_action'], ACTION)
        self.assertEqual([i['name'] for i in relay['instructions']],
                         ['to_the_recorded_start', 'move_to_near_pick', 'move_to_pick', 'close_gripper',
                          'back_to_near_pick', 'move_to_final', 'open_gripper'])
        self.assertEqual(relay['succeeded'], 7, relay)
        # the driver got the arm's goals only (the gripper ran in simulation), after the preview and confirmation
        with open(self.goals) as f:
            received = [json.loads(line) for line in f]
        arm = [i for i in relay['instructions'] if i['name'] in ARM]
        self.assertEqual(len(received), len(arm))
        for goal, sent in zip(received, arm):
            self.assertEqual(goal['joint_names'], JOINTS, sent['name'])  # the robot's prefix stripped
            self.assertEqual(goal['points'], sent['points'], sent['name'])
            self.assertAlmostEqual(goal['seconds'], sent['seconds'], places=3, msg=sent['name'])
        # the first goal starts where the real arm stood (the stand-in at zero), each next where the last ended
        self.assertTrue(all(abs(q) < 1e-9 for q in received[0]['first']), received[0]['first'])
        for before, after in zip(received, received[1:]):
            self.assertLess(max(abs(a - b) for a, b in zip(before['last'], after['first'])), 0.01)

    def test_a_namespace_without_a_driver_stops_before_the_teach(self):
        start = time.monotonic()
        result = demo('--quick', '--real', '/nobody', env=self.env, timeout=60)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn('no driver action /nobody/scaled_pos_joint_traj_controller/follow_joint_trajectory',
                      result.stderr)
        self.assertNotIn('1 teach', result.stdout)
        self.assertLess(time.monotonic() - start, 30.0)

    def test_no_master_and_yes_alone_are_one_line(self):
        env = dict(self.env, ROS_MASTER_URI=f'http://127.0.0.1:{free_port()}')
        result = demo('--quick', '--real', '/stand_in', env=env, timeout=60)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn('--real: no ROS master at ' + env['ROS_MASTER_URI'], result.stderr)
        result = demo('--quick', '--yes', env=self.env, timeout=60)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn('--yes confirms --real NS', result.stderr)


if __name__ == '__main__':
    unittest.main()
