#!/usr/bin/python3
"""`./vrrw skill` refusing bad input as a user meets it, without a workspace: each is one line naming the file,
field or option and the reason, exit 2 (exit 1 for no workspace), nothing written, nothing started. And an
evaluate killed mid-run (SIGKILL: no clean-up of its own) leaves none of its workspace's processes running.
About 40 seconds."""
import os
import re
import signal
import shutil
import socket
import subprocess
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '../../../..'))
VRRW = os.path.join(ROOT, 'vrrw')
BOX_CELL = os.path.join(HERE, 'data', 'box_cell.yaml')


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


class SkillToolBadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.mkdtemp(prefix='vrrw_skill_tool_')
        cls.env = dict(os.environ, ROS_MASTER_URI=f'http://localhost:{free_port()}')  # nobody listens there
        cls.skill = os.path.join(HERE, 'data', 'box_skill.yaml')  # learned from a box taught in box_cell.yaml

    def refuse(self, arguments, expected, exit_code=2):
        start = time.monotonic()
        result = subprocess.run([VRRW, 'skill'] + arguments, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                text=True, env=self.env, timeout=60)
        self.assertEqual(result.returncode, exit_code, result.stderr)
        lines = result.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn(expected, lines[0])
        return time.monotonic() - start

    def test_learn(self):
        out = os.path.join(self.folder, 'never.yaml')
        self.refuse(['learn', '/nonexistent/demo.bag', '--object', 'box', '--out', out],
                    '/nonexistent/demo.bag: no such file')
        garbage = os.path.join(self.folder, 'cut.bag')
        with open(garbage, 'wb') as f:
            f.write(b'#ROSBAG V2.0\n' + b'\0' * 100)
        self.refuse(['learn', garbage, '--object', 'box', '--out', out], './vrrw demos recover')
        self.refuse(['learn', '--object', 'box', '--out', out], 'missing BAG')
        self.refuse(['learn', garbage, '--out', out], '--object')
        self.assertFalse(os.path.exists(out))

    def test_skill_files(self):
        truncated = os.path.join(self.folder, 'truncated.yaml')
        with open(truncated, 'w') as f:
            f.write('format: vrrw_skills/1\nrobot: {name: ur5e, arm_joints: [a, b\n')
        self.refuse(['evaluate', truncated, '--scene', BOX_CELL], truncated + ':')
        other = os.path.join(self.folder, 'other.yaml')
        with open(other, 'w') as f:
            f.write('format: vrrw_skills/9\n')
        self.refuse(['run', other], "format: 'vrrw_skills/9' is not 'vrrw_skills/1' (a skill of another version)")
        self.refuse(['run', os.path.join(self.folder, 'missing.yaml')], 'cannot open for reading')

    def test_evaluate_checks_everything_before_it_starts(self):
        out = os.path.join(self.folder, 'evaluation')
        self.refuse(['evaluate', self.skill, '--scene', 'pick_place_drill', '--out', out],
                    "pick_place_drill: objects: no object 'box' (the scene has: table, drill, bin)")
        self.refuse(['evaluate', self.skill, '--scene', BOX_CELL, '--robot', 'ur10e', '--out', out],
                    "robots: no robot 'ur10e' (the scene has: ur5e)")
        self.refuse(['evaluate', self.skill, '--scene', 'no_such_cell', '--out', out], 'no_such_cell')
        self.refuse(['evaluate', self.skill, '--scene', BOX_CELL, '--trials', '0', '--out', out], '--trials')
        self.refuse(['evaluate', self.skill, '--scene', BOX_CELL, '--spread', '0.1,-0.1,30', '--out', out],
                    '--spread')
        self.refuse(['evaluate', self.skill, '--scene', BOX_CELL, '--spread', '0.1,0.1', '--out', out], '--spread')
        for rtf in ('0', '-2', 'nan', 'fast'):
            self.refuse(['evaluate', self.skill, '--scene', BOX_CELL, '--rtf', rtf, '--out', out],
                        f"--rtf: '{rtf}' is not max or a positive number (the real-time factor)")
        self.assertFalse(os.path.exists(out))

    def test_evaluate_refuses_a_port_in_use(self):
        # VRRW_ROS_PORT where a master (the user's workspace) listens: evaluate would add its nodes to it
        out = os.path.join(self.folder, 'evaluation_port')
        with socket.socket() as taken:
            taken.bind(('', 0))
            taken.listen()
            port = taken.getsockname()[1]
            result = subprocess.run([VRRW, 'skill', 'evaluate', self.skill, '--scene', BOX_CELL, '--out', out],
                                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60,
                                    env=dict(self.env, VRRW_ROS_PORT=str(port)))
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertEqual(result.stderr.strip(), f'skill evaluate: VRRW_ROS_PORT: port {port} is in use (a running '
                                                'workspace?); evaluate starts its own: unset it or choose a free port')
        self.assertFalse(os.path.exists(out))

    def test_run_without_a_workspace_says_so_quickly(self):
        seconds = self.refuse(['run', self.skill], 'no workspace at ', exit_code=1)
        self.assertLess(seconds, 10.0)  # the check itself answers within 2 s; the tool's start is the rest


class KilledEvaluation(unittest.TestCase):
    def test_an_evaluate_killed_mid_run_takes_its_workspace_with_it(self):
        folder = tempfile.mkdtemp(prefix='vrrw_skill_killed_')
        out = os.path.join(folder, 'evaluation')
        skill = os.path.join(HERE, 'data', 'box_skill.yaml')
        evaluate = subprocess.Popen([VRRW, 'skill', 'evaluate', skill, '--scene', BOX_CELL, '--trials', '3',
                                     '--out', out], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        try:
            for line in evaluate.stdout:  # the workspace is up and the first trial runs
                if 'trial 1/3' in line:
                    break
            with open(os.path.join(out, 'workspace.log')) as log:
                pids = [int(p) for p in re.findall(r'started with pid \[(\d+)\]', log.read())]
            self.assertGreaterEqual(len(pids), 6)  # master, rosout and the workspace's nodes
            self.assertTrue(all(alive(pid) for pid in pids))
        finally:
            evaluate.send_signal(signal.SIGKILL)
            evaluate.wait()
        deadline = time.monotonic() + 15.0  # the watchdog's SIGTERM, then SIGKILL 5 s after
        while any(alive(pid) for pid in pids) and time.monotonic() < deadline:
            time.sleep(0.2)
        self.assertEqual([pid for pid in pids if alive(pid)], [])
        shutil.rmtree(folder)


def alive(pid):
    try:
        with open(f'/proc/{pid}/stat') as stat:
            return stat.read().split(') ')[1][0] != 'Z'
    except (FileNotFoundError, IndexError):
        return False


if __name__ == '__main__':
    unittest.main()
