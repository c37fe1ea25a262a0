"""./vrrw up's processes: it names its own PIDs, a node that dies before ready is named and stops the workspace,
and nothing outlives the launcher: not after Ctrl-C, not after SIGINT or SIGTERM to the launcher alone, not after
SIGKILL of its process group."""
import os
import queue
import re
import signal
import socket
import subprocess
import tempfile
import threading
import time
import unittest

ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(os.path.dirname(__file__), '../../../..')))
VRRW = os.path.join(ROOT, 'vrrw')


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def start_time(pid):
    try:
        with open(f'/proc/{pid}/stat') as f:
            return f.read().rsplit(') ', 1)[1].split()[19]
    except (OSError, IndexError):
        return None


class Workspace:
    """./vrrw up SCENE in a process group of its own on a free port; its output line by line."""

    def __init__(self, *args):
        env = dict(os.environ, ROS_MASTER_URI=f'http://localhost:{free_port()}', ROS_HOME=tempfile.mkdtemp())
        self.process = subprocess.Popen([VRRW, 'up', *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        text=True, env=env, start_new_session=True)
        self.lines, self.output = queue.Queue(), []
        threading.Thread(target=self._read, daemon=True).start()
        self.started = {}  # pid: start time of every process roslaunch reported

    def _read(self):
        for line in self.process.stdout:
            self.lines.put(line)
        self.lines.put(None)

    def wait_for(self, pattern, seconds=120):
        """The first line matching pattern (a regex), or None when the output ended or time ran out."""
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            try:
                line = self.lines.get(timeout=1)
            except queue.Empty:
                continue
            if line is None:
                return None
            self.output.append(line)
            started = re.search(r'process\[.*\]: started with pid \[(\d+)\]', line)
            if started:
                self.started[int(started.group(1))] = start_time(int(started.group(1)))
            found = re.search(pattern, line)
            if found:
                return found
        return None

    def alive(self, pids):
        return [pid for pid, start in pids.items() if start is not None and start_time(pid) == start]

    def wait_until_gone(self, pids, seconds=30):
        end = time.monotonic() + seconds
        while self.alive(pids) and time.monotonic() < end:
            time.sleep(0.2)
        return self.alive(pids)

    def stop(self):
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGINT)
            self.process.wait(timeout=60)
        self.process.stdout.close()


class Lifecycle(unittest.TestCase):
    def test_sigkill_of_the_launchers_group_ends_every_node(self):
        workspace = Workspace('pick_place_drill', '--mode', 'fake')
        try:
            own = workspace.wait_for(r'this launcher is PID (\d+) \(process group (\d+)\); watchdog PID (\d+)')
            self.assertIsNotNone(own, ''.join(workspace.output))
            self.assertEqual(own.group(1), str(workspace.process.pid))
            listed = workspace.wait_for(r'^vrrw: PIDs of the workspace: (.*)$')
            self.assertIsNotNone(listed, ''.join(workspace.output))
            pids = {int(pid): start_time(int(pid)) for pid in re.findall(r' (\d+)', ' ' + listed.group(1))}
            names = re.findall(r'([a-z_]+) \d+', listed.group(1))
            for node in ('roslaunch', 'rosmaster', 'scene_node', 'planning_node', 'controller_node'):
                self.assertIn(node, names, listed.group(1))
            killed = time.monotonic()
            os.killpg(workspace.process.pid, signal.SIGKILL)
            workspace.process.wait(timeout=10)
            left = workspace.wait_until_gone(pids)
            print(f'{len(pids)} processes of the workspace gone {time.monotonic() - killed:.1f} s after SIGKILL')
            self.assertEqual(left, [], f'still running after 30 s: {left}')
        finally:
            workspace.stop()

    def test_a_node_that_dies_before_ready_is_named_and_stops_the_workspace(self):
        workspace = Workspace('pick_place_drill', '--mode', 'fake')
        try:
            planner = workspace.wait_for(r'process\[planning_node-\d+\]: started with pid \[(\d+)\]')
            self.assertIsNotNone(planner, ''.join(workspace.output))
            os.kill(int(planner.group(1)), signal.SIGKILL)  # before it ever answers: no ready
            self.assertIsNotNone(workspace.wait_for(r'^vrrw: not ready: planning_node died'), ''.join(workspace.output))
            self.assertEqual(workspace.process.wait(timeout=90), 1)
            self.assertFalse(any(line.startswith('ready:') for line in workspace.output))
            self.assertEqual(workspace.wait_until_gone(workspace.started), [])
        finally:
            workspace.stop()

    def test_ctrl_c_ends_the_workspace_whole(self):
        workspace = Workspace('pick_place_drill', '--mode', 'fake')
        try:
            self.assertIsNotNone(workspace.wait_for(r'^ready: 1 robot \(ur5e\), mode fake'), ''.join(workspace.output))
            os.killpg(workspace.process.pid, signal.SIGINT)
            self.assertEqual(workspace.process.wait(timeout=60), 0)
            self.assertEqual(workspace.wait_until_gone(workspace.started), [])
        finally:
            workspace.stop()

    def test_sigint_or_sigterm_to_the_launcher_alone_ends_the_workspace_whole(self):
        # what `kill PID` from another shell does: before, roslaunch (the launcher's foreground child) never heard
        # of a SIGINT, and a SIGTERM killed the launcher and left the nodes to the watchdog
        for sent in (signal.SIGINT, signal.SIGTERM):
            workspace = Workspace('pick_place_drill', '--mode', 'fake')
            try:
                ready = workspace.wait_for(r'^ready: 1 robot \(ur5e\), mode fake')
                self.assertIsNotNone(ready, ''.join(workspace.output))
                workspace.process.send_signal(sent)
                self.assertEqual(workspace.process.wait(timeout=60), 0, sent)
                self.assertEqual(workspace.wait_until_gone(workspace.started), [], sent)
            finally:
                workspace.stop()

    def test_a_scene_beyond_any_cell_stops_before_any_node(self):
        result = subprocess.run([VRRW, 'up', os.path.join(ROOT, 'test', 'bad_input', 'far_base.yaml')],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        self.assertEqual(result.returncode, 2)  # bad input
        self.assertRegex(result.stderr, r'^vrrw_scene: .*far_base.yaml:6: robots\[0\]\.base\.xyz: 1e\+30 outside '
                                        r'\[-100, 100\] m \(a cell.s coordinates\)\n$')


if __name__ == '__main__':
    unittest.main()
