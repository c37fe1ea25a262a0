"""./vrrw's options: every mistake is one line naming the option, exit 2, checked before anything is
started, written or deleted; tools that need a workspace say so within seconds when none runs."""
import glob
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(os.path.dirname(__file__), '../../../..')))
VRRW = os.path.join(ROOT, 'vrrw')
sys.path.insert(0, os.path.join(ROOT, 'catkin_ws', 'src', 'vrrw_evaluation', 'scripts'))


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def vrrw(*args, master_port=None, **environment):
    env = dict(os.environ, **environment)
    if master_port:  # nothing listens there
        env['ROS_MASTER_URI'] = f'http://localhost:{master_port}'
    start = time.monotonic()
    result = subprocess.run([VRRW, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                            timeout=60)
    result.seconds = time.monotonic() - start
    return result


class Refusals(unittest.TestCase):
    def refused(self, line, *args, code=2, **environment):
        result = vrrw(*args, **environment)
        self.assertEqual((result.returncode, result.stderr), (code, line + '\n'), result.stdout)
        return result

    def test_demo_validates_every_option_before_touching_its_out_directory(self):
        out = tempfile.mkdtemp(prefix='vrrw_options_')
        os.makedirs(os.path.join(out, 'frames'))
        with open(os.path.join(out, 'workspace.log'), 'w') as f:
            f.write('an earlier run\n')
        self.refused('vrrw: demo: --trials: -1 is not a whole number >= 0', 'demo', '--out', out, '--trials', '-1')
        self.refused('vrrw: demo: --trials: 2.5 is not a whole number >= 0', 'demo', '--out', out, '--trials', '2.5')
        self.refused("vrrw: demo: --trials: 'many' is not a whole number >= 0", 'demo', '--trials', 'many')
        self.refused('vrrw: demo: --trials: 5000 outside [0, 1000]', 'demo', '--out', out, '--trials', '5000')
        self.refused('vrrw: demo: --trials: needs a value', 'demo', '--out', out, '--trials')
        self.refused('vrrw: demo: --trials: needs a value', 'demo', '--trials', '--quick')
        self.refused('vrrw: demo: --seed: -3 is not a whole number >= 0', 'demo', '--seed', '-3')
        self.refused('vrrw: demo: unknown option --trails', 'demo', '--trails', '5')
        self.refused('vrrw: demo: --quick: takes no value', 'demo', '--quick=yes')
        self.refused("vrrw: demo: unexpected argument 'extra'", 'demo', 'extra')
        self.refused('vrrw: demo: --yes confirms --real NS, which was not given', 'demo', '--yes')
        for rtf in ('0', '-1', 'nan', 'fast'):
            self.refused(f"vrrw: demo: --rtf: '{rtf}' is not max or a positive number (the real-time factor; 1: "
                         "paced at real time)", 'demo', '--out', out, '--rtf', rtf)
        for display in ('x', ':a', '123456'):
            self.refused(f"demo: VRRW_DISPLAY: '{display}' is not an X display number (64 or :64)", 'demo', '--out',
                         out, VRRW_DISPLAY=display)
        self.refused("demo: VRRW_ROS_PORT: '1e4' is not a port number (11311)", 'demo', '--out', out,
                     VRRW_ROS_PORT='1e4')
        with socket.socket() as taken:  # a running workspace's master on the port: never joined
            taken.bind(('127.0.0.1', 0))
            taken.listen()
            port = taken.getsockname()[1]
            self.refused(f'demo: VRRW_ROS_PORT: port {port} is in use (a running workspace?); demo starts its own: '
                         'unset it or choose a free port', 'demo', '--out', out, VRRW_ROS_PORT=str(port))
        self.assertTrue(os.path.isdir(os.path.join(out, 'frames')))
        with open(os.path.join(out, 'workspace.log')) as f:
            self.assertEqual(f.read(), 'an earlier run\n')

    def test_demo_out_must_be_a_directory_it_can_write(self):
        with tempfile.NamedTemporaryFile() as existing:
            self.refused(f'vrrw: demo: --out: {existing.name}: exists and is not a directory',
                         'demo', '--out', existing.name)
        self.refused('vrrw: demo: --out: /proc: not writable', 'demo', '--out', '/proc/vrrw_report')

    def test_up_and_test(self):
        self.refused('vrrw: up: --mode: needs a value', 'up', 'pick_place_drill', '--mode')
        self.refused("vrrw: up: --mode: 'phys' is not one of fake physics none", 'up', 'pick_place_drill',
                     '--mode', 'phys')
        self.refused('vrrw: up: missing SCENE', 'up', '--mode', 'fake')
        self.refused('vrrw_scene: x$(env HOME): no such scene file or shipped scene (shipped: paper_multibot, '
                     'pick_place_drill)', 'up', 'x$(env HOME)')
        self.refused('vrrw: test: --repeat: 0 is not a whole number >= 1', 'test', '--repeat', '0')

    def test_a_workspace_never_joins_a_running_one(self):
        port = free_port()
        uri = f'http://localhost:{port}'
        env = dict(os.environ, ROS_MASTER_URI=uri)
        master = subprocess.Popen(['rosmaster', '--core', '-p', str(port)], env=env, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL, start_new_session=True)
        scene = None
        try:
            # a running workspace: its /scene node (a stand-in that only registers, on a real master)
            scene = subprocess.Popen([sys.executable, '-c', 'import rospy; rospy.init_node("scene"); rospy.spin()'],
                                     env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                     start_new_session=True)
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline:
                listed = subprocess.run(['rosnode', 'list'], env=env, capture_output=True, text=True).stdout
                if '/scene' in listed.split():
                    break
                time.sleep(0.2)
            for what, args in (('up', ('up', 'pick_place_drill')),
                               ('record', ('record', 'pick_place_drill', '--out', tempfile.mktemp(suffix='.bag')))):
                self.refused(f'vrrw: {what}: a workspace already runs at {uri} (its /scene node): stop it, or set '
                             'ROS_MASTER_URI to a free port', *args, ROS_MASTER_URI=uri)
        finally:
            for process in (scene, master):
                if process:
                    os.killpg(process.pid, signal.SIGTERM)
                    process.wait(timeout=10)

    def test_record_refuses_before_recording(self):
        with tempfile.NamedTemporaryFile(suffix='.bag') as existing:
            self.refused(f'vrrw record: --out: {existing.name}: exists; not overwritten (remove it or choose another '
                         'name)', 'record', 'running', '--out', existing.name)
        self.refused('vrrw: record: --out: required (FILE.bag)', 'record', 'running')
        self.refused("vrrw: record: --robots: 'a b' is not a list of robot names (a,b)", 'record', 'running',
                     '--out', '/tmp/vrrw_never.bag', '--robots', 'a b')
        self.refused('vrrw record: --out: /nonexistent_dir/a.bag: cannot create a file in /nonexistent_dir (No such '
                     'file or directory)', 'record', 'running', '--out', '/nonexistent_dir/a.bag')

    def test_scene_writes_its_urdf_beside_timing_and_robots(self):
        folder = tempfile.mkdtemp(prefix='vrrw_options_')
        for extra, stdout_start in (('--robots', 'ur5e\n'), ('--timing', '{"scene": "pick_place_drill"')):
            urdf = os.path.join(folder, extra[2:] + '.urdf')
            result = vrrw('scene', 'pick_place_drill', extra, '--urdf-out', urdf)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertTrue(result.stdout.startswith(stdout_start), result.stdout)
            with open(urdf) as f:
                self.assertIn('<robot name=', f.read())
        self.refused('vrrw_scene: unknown option --urdf\nusage: vrrw_scene SCENE [--urdf-out FILE|-] [--robots] '
                     '[--timing] [--no-cache]\n  SCENE is a shipped scene name or a scene YAML path; --robots prints the '
                     'robot names', 'scene', 'pick_place_drill', '--urdf', 'x')

    def test_an_explicit_trials_beats_the_quick_preset(self):
        import run_demo
        self.assertEqual(run_demo.parse_args(['--launch', 'x', '--quick', '--trials', '5']).trials, 5)
        self.assertEqual(run_demo.parse_args(['--launch', 'x', '--quick']).trials, 3)
        self.assertEqual(run_demo.parse_args(['--launch', 'x']).trials, 20)


class Documented(unittest.TestCase):
    """Every command ./vrrw runs and every benchmark there is, is in ./vrrw --help and in the README's Commands table."""

    @classmethod
    def setUpClass(cls):
        with open(VRRW) as f:
            dispatch = re.search(r'^  (setup \|[^)]*)\) "cmd_', f.read(), re.M).group(1)
        cls.commands = [c.strip() for c in dispatch.split('|')]
        cls.help = vrrw('--help').stdout
        with open(os.path.join(ROOT, 'README.md')) as f:
            readme = f.read()
        cls.table = readme[readme.index('## Commands'):readme.index('## Layout')]
        unknown = vrrw('bench', 'no_such_benchmark')  # names every benchmark there is
        cls.benchmarks = sorted(re.fullmatch(r"vrrw: bench: no benchmark named 'no_such_benchmark' \(known: ([^)]*)\)\n",
                                             unknown.stderr).group(1).split())

    def test_every_command_in_help_and_readme(self):
        self.assertIn('plan', self.commands)
        for command in self.commands:
            self.assertRegex(self.help, rf'\n  {command}\b', command)
            self.assertIn(f'| `./vrrw {command}', self.table, command)

    def test_every_benchmark_in_help_and_readme(self):
        self.assertIn('interaction', self.benchmarks)
        listed = re.search(r'run a benchmark \(([^)]*)\)', self.help).group(1).split()
        self.assertEqual(sorted(listed), self.benchmarks)
        in_readme = re.search(r'benchmarks \(`([^`]*)`', self.table).group(1).split()
        self.assertEqual(sorted(in_readme), self.benchmarks)

    def test_the_presets_the_readmes_name_exist_in_pick_place_drill(self):
        import yaml
        with open(os.path.join(ROOT, 'urdf', 'config', 'presets.yaml')) as f:
            presets = set(yaml.safe_load(f)['ur5e'])
        with open(os.path.join(ROOT, 'urdf', 'scenes', 'pick_place_drill.yaml')) as f:
            presets |= set((yaml.safe_load(f).get('presets') or {}).get('ur5e', {}))
        texts = [os.path.join(ROOT, 'README.md')] + glob.glob(os.path.join(ROOT, 'catkin_ws', 'src', '*', 'README.md'))
        named = set()
        for path in texts:
            with open(path) as f:
                text = f.read()
            for groups in re.findall(r'preset "name: (\w+)"|--preset (\w+)|ghost at `?(\w+_\w+)', text):
                named |= {name for name in groups if name}
            for known in re.findall(r"unknown\s+preset\s+'\w+'\s+\(known:\s+([^)]*)\)", text):
                self.assertEqual(set(known.replace(',', ' ').split()), presets, path)
        self.assertIn('square_left', named)
        self.assertLessEqual(named - {'NAME'}, presets)


class HostileScenePath(unittest.TestCase):
    """record SCENE takes a scene path as a file path, whatever its characters: none becomes shell or launch text."""

    def test_record_brings_up_a_scene_named_in_shell_and_launch_syntax(self):
        folder = tempfile.mkdtemp(prefix='vrrw_hostile_')
        cwd = os.path.join(folder, 'd $(touch PWNED) |&')
        os.makedirs(cwd)
        scene = "scene:=a';touch PWNED;'.yaml"  # relative: the word roslaunch would read as an argument
        shutil.copy(os.path.join(ROOT, 'urdf', 'scenes', 'pick_place_drill.yaml'), os.path.join(cwd, scene))
        bag = os.path.join(cwd, "rec';touch PWNED;'.bag")
        ros_home = tempfile.mkdtemp(prefix='vrrw_hostile_home_')
        self.addCleanup(shutil.rmtree, folder)
        self.addCleanup(shutil.rmtree, ros_home)
        env = dict(os.environ, ROS_MASTER_URI=f'http://localhost:{free_port()}', ROS_HOME=ros_home)
        record = subprocess.Popen([VRRW, 'record', scene, '--out', bag], cwd=cwd, env=env, text=True,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
        output = []
        try:
            for line in record.stdout:  # up to the first progress line: the workspace came up and records
                output.append(line)
                if re.match(r'record: \d+ s, \d+ messages', line):
                    os.killpg(record.pid, signal.SIGINT)  # Ctrl-C: stops the recording, then the scene
                    break
            rest = record.communicate(timeout=60)[0]
        finally:
            if record.poll() is None:
                os.killpg(record.pid, signal.SIGKILL)
                record.wait()
        text = ''.join(output) + rest
        self.assertEqual(record.returncode, 0, text)
        stopped = re.search(r'^record: stopped: (\d+) messages in (.*)$', text, re.M)
        self.assertIsNotNone(stopped, text)
        print(stopped.group(0))
        self.assertEqual(stopped.group(2), bag)
        import rosbag
        with rosbag.Bag(bag) as recorded:
            topics = recorded.get_type_and_topic_info().topics
            self.assertEqual(recorded.get_message_count(), int(stopped.group(1)))
        self.assertGreater(int(stopped.group(1)), 0)
        self.assertGreater(topics['/ur5e/joint_states'].message_count, 0)  # the scene's robot
        pwned = glob.glob(os.path.join(folder, '**', 'PWNED'), recursive=True) + \
            glob.glob(os.path.join(ros_home, '**', 'PWNED'), recursive=True) + \
            [where for where in (os.getcwd(), ROOT, os.path.join(ROOT, 'build', 'ros_home'))
             if os.path.exists(os.path.join(where, 'PWNED'))]
        self.assertEqual(pwned, [])

    def test_record_refuses_a_scene_argument_that_names_no_scene(self):
        result = vrrw('record', 'scene:=pick_place_drill', '--out', os.path.join(tempfile.mkdtemp(), 'a.bag'))
        self.assertEqual(result.returncode, 2, result.stderr)
        line = ('vrrw_scene: scene:=pick_place_drill: no such scene file or shipped scene (shipped: paper_multibot, '
                'pick_place_drill)\n')
        self.assertTrue(result.stderr.endswith(line), result.stderr)  # after any build lines of ./vrrw's own
        self.assertNotIn('bringing up', result.stdout)


class WithoutWorkspace(unittest.TestCase):
    """No master at ROS_MASTER_URI: one line within the check's 2 s, exit 1 (roscpp would retry forever)."""

    def check(self, *args, line_start):
        port = free_port()
        result = vrrw(*args, master_port=port)
        print(f'{" ".join(args)}: answered in {result.seconds:.1f} s')
        self.assertEqual(result.returncode, 1, result.stderr)
        self.assertEqual(result.stderr, f'{line_start}no workspace at http://localhost:{port}: start one with '
                                        './vrrw up SCENE\n')
        self.assertLess(result.seconds, 30.0)  # bounded; only a hang fails this

    def test_send(self):
        self.check('send', 'ur5e', '--joints', '0,-1.57,1.57,-1.57,-1.57,0', line_start='vrrw_arm: ')

    def test_move(self):
        self.check('move', 'ur5e', '--joints', '0,-1.57,1.57,-1.57,-1.57,0', line_start='vrrw_arm: ')

    def test_plan(self):
        self.check('plan', 'ur5e', '--preset', 'square_left', line_start='vrrw_plan: ')

    def test_skill_run(self):
        skill = os.path.join(ROOT, 'catkin_ws', 'src', 'vrrw_skills', 'test', 'data', 'box_skill.yaml')
        self.check('skill', 'run', skill, line_start='skill run: ')

    def test_record_running(self):
        self.check('record', 'running', '--out', os.path.join(tempfile.mkdtemp(), 'a|b.bag'),
                   line_start='vrrw record: ')

    def test_demos_replay(self):
        folder = tempfile.mkdtemp(prefix='vrrw_options_')
        csv, bag = os.path.join(folder, 'demo.csv'), os.path.join(folder, 'demo.bag')
        with open(csv, 'w') as f:
            f.write('t,q1,q2,q3,q4,q5,q6,qd1,qd2,qd3,qd4,qd5,qd6,gripper\n')
            for k in range(3):
                f.write(f'{0.1 * k},{0.01 * k},-1.57,1.57,-1.57,-1.57,0,0.1,0,0,0,0,0,0\n')
        imported = vrrw('demos', 'import', csv, '--bag', bag, '--robot', 'ur5e')
        self.assertEqual(imported.returncode, 0, imported.stderr)
        self.check('demos', 'replay', bag, '--mode', 'fake', line_start='vrrw demos replay: ')


if __name__ == '__main__':
    unittest.main()
