"""./vrrw demo --quick as a user runs it (lockstep at --rtf max, the default), with the issue's numbers in
metrics.json; the README's DMP example on its demonstration.bag as written there; and the bad inputs (unknown
scene, a scene without a graspable object) as one clear line. No figure here depends on the wall clock (its speed
is `./vrrw bench`'s and the README's)."""
import json
import os
import re
import shlex
import subprocess
import tempfile
import time
import unittest

import yaml

ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(os.path.dirname(__file__), '../../../..')))
VRRW = os.path.join(ROOT, 'vrrw')


def demo(*args, timeout=300):
    return subprocess.run([VRRW, 'demo', *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=timeout)


class QuickDemoTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # a report folder whose name a shell would run: the frames are captured without one
        cls.out = tempfile.mkdtemp(prefix="vrrw_demo_test_';touch PWNED;'")
        start = time.monotonic()
        cls.result = demo('--quick', '--seed', '3', '--out', cls.out)
        cls.seconds = time.monotonic() - start
        print(cls.result.stdout[-4000:])
        with open(os.path.join(cls.out, 'metrics.json')) as f:
            cls.metrics = json.load(f)

    def test_runs_to_its_report(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr[-2000:])
        print(f'./vrrw demo --quick: {self.seconds:.1f} s from the command to the report (runner '
              f'{self.metrics["wall_seconds"]:.1f} s, physics rtf {self.metrics["physics"]["rtf"]:.1f}; '
              f'load average {os.getloadavg()[0]:.1f})')
        self.assertNotIn('TF_REPEATED_DATA', self.result.stdout + self.result.stderr)

    def test_teach_and_segments(self):
        self.assertGreater(self.metrics['teach']['seconds'], 3.0)
        self.assertGreater(self.metrics['bag']['messages'], 300)
        names = [s['name'] for s in self.metrics['segments']]
        self.assertEqual(names, ['move_to_near_pick', 'move_to_pick', 'close_gripper', 'back_to_near_pick',
                                 'move_to_final', 'open_gripper'])
        for before, after in zip(self.metrics['segments'], self.metrics['segments'][1:]):
            self.assertLess(before['start'], before['end'])
            self.assertLessEqual(before['end'], after['start'] + 1e-6)

    def test_the_keyframe_rule_finds_the_scripts_instructions(self):
        # `./vrrw demos segment` reads only arm speeds and gripper actions, not the script's annotations. Its
        # boundaries are where motion starts and stops, the script's where its calls start and return (the open
        # returns before the fingers stop): 0.41-0.45 s apart at most in quick runs. A motion given to the wrong
        # instruction would move a boundary by a whole motion, 1.2 s at least (the free-drive descent).
        found_file = os.path.join(self.out, 'keyframe.segments.yaml')
        result = subprocess.run([VRRW, 'demos', 'segment', self.metrics['bag']['file'], '--out', found_file],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(found_file) as f:
            found = yaml.safe_load(f)
        keyframe = found['robots']['ur5e']['segments']
        words = {'near_pick': 'move_to_near_pick', 'pick': 'move_to_pick', 'final': 'move_to_final'}
        self.assertEqual([words.get(k['name'], k['name']) for k in keyframe], [s['name'] for s in self.metrics['segments']])
        shift = found['start_stamp'] - self.metrics['teach']['start_stamp']
        worst = max(max(abs(k['start'] + shift - s['start']), abs(k['end'] + shift - s['end']))
                    for k, s in zip(keyframe, self.metrics['segments']))
        print(f'keyframe rule: every boundary within {worst:.3f} s of the script\'s')
        self.assertLess(worst, 1.0)

    def test_teach_only_through_operator_interfaces(self):
        used = self.metrics['teach']['interfaces']
        self.assertEqual(sorted(used), sorted(s['name'] for s in self.metrics['segments']))
        for name in ['move_to_near_pick', 'back_to_near_pick', 'move_to_final']:
            self.assertIn('/ur5e/ghost/plan', used[name])
            self.assertIn('/ur5e/ghost/execute', used[name])
            self.assertTrue(all(s.startswith('/ur5e/ghost/') for s in used[name]), used[name])
        self.assertIn('/ur5e/ghost/add_waypoint', used['move_to_near_pick'])
        # free-drive down to the grasp: a hand grabs the wrist
        self.assertEqual(used['move_to_pick'], ['/ur5e/free_drive', '/operator/right/pose', '/operator/right/grip'])
        self.assertIn('/ur5e/ghost/set_support_surface', used['move_to_final'])  # the place onto the table
        for name in ['close_gripper', 'open_gripper']:
            self.assertEqual(used[name], ['/ur5e/gripper_controller/gripper_cmd'])

    def test_replay_reproduces_the_demonstration(self):
        replay = self.metrics['replay']
        # The target is the drill's pose; the joint error is reported (1.5e-3 rad on a quiet
        # machine, 6e-3 rad measured at load average 10, when physics kept 0.9 of real time).
        self.assertLess(replay['joint_rms_rad'], 1e-2)
        self.assertLess(replay['object_position_error_m'], 0.01)
        self.assertLess(replay['object_angle_error_deg'], 5.0)

    def test_dmp_trials(self):
        dmp = self.metrics['dmp']
        self.assertEqual(dmp['trials'], 3)
        # the target is 90 %: 2 of 3 would be a regression. Measured: 3 of 3 in every quick run (README: 4 runs;
        # two test runs of main on this machine: final drill 1.1-2.0 mm from the place)
        self.assertEqual(dmp['success_rate'], 1.0, dmp['failures'])
        self.assertEqual(len(dmp['failures']), 0)
        for trial in dmp['trial_results']:
            print(f"trial {trial.get('trial')}: final drill {trial['final_error_m'] * 1e3:.1f} mm from the place")
            self.assertLess(trial['final_error_m'], 0.01)

    def test_skill_grasp_as_the_script_meant_it(self):
        # issue 19: the grasp skill learn finds in the bag within 2 mm / 1 deg of the teach script's own
        # (0.73 mm / 0.18 deg measured: the drill settles a little in the closing fingers)
        skill = self.metrics['skill']
        self.assertLess(skill['grasp_error_mm'], 2.0)
        self.assertLess(skill['grasp_error_deg'], 1.0)

    def test_a_second_run_with_the_seed_writes_the_same_files(self):
        # issue 20: the same seed gives identical data/ files and metrics.json apart from wall-clock fields,
        # the bag's message count included (6009 in five runs of seed 4711, one with a busy loop per core)
        out = tempfile.mkdtemp(prefix='vrrw_demo_again_')
        again = demo('--quick', '--seed', '3', '--out', out)
        self.assertEqual(again.returncode, 0, again.stderr[-2000:])
        files = sorted(os.listdir(os.path.join(self.out, 'data')))
        self.assertEqual(files, sorted(os.listdir(os.path.join(out, 'data'))))
        differing = []
        for name in files:
            with open(os.path.join(self.out, 'data', name), 'rb') as a, open(os.path.join(out, 'data', name), 'rb') as b:
                if a.read() != b.read():
                    differing.append(name)
        self.assertEqual(differing, [], f'{len(differing)} of {len(files)} data files differ')
        with open(os.path.join(out, 'metrics.json')) as f:
            second = json.load(f)
        wall_clock = {'ik_ms', 'plan_ms', 'learn_seconds', 'stage_seconds', 'wall_seconds', 'rtf', 'file'}

        def fields(value, path=''):
            if isinstance(value, dict):
                return {k: v for key, item in value.items() if key not in wall_clock
                        for k, v in fields(item, f'{path}.{key}').items()}
            if isinstance(value, list):
                return {k: v for i, item in enumerate(value) for k, v in fields(item, f'{path}[{i}]').items()}
            return {path: value}
        first, later = fields(self.metrics), fields(second)
        self.assertEqual({k for k in first.keys() | later.keys() if first.get(k) != later.get(k)}, set())
        print(f'seed 3 twice: {len(files)} data files identical, bag {second["bag"]["messages"]} messages in both')

    def test_the_achieved_rtf_is_reported_and_the_report_is_whole(self):
        # lockstep at rtf max: simulated s per wall s as achieved (2.2-2.9 at load 18 on 2 cores)
        self.assertGreater(self.metrics['physics']['rtf'], 0.0)
        for name in ('index.html', 'report.md', 'joints.png', 'top_view.png', 'strips.png'):
            self.assertGreater(os.path.getsize(os.path.join(self.out, name)), 1000, name)
        self.assertEqual(len([f for f in os.listdir(os.path.join(self.out, 'frames')) if f.endswith('.png')]), 18)
        self.assertFalse(os.path.exists('PWNED'))  # the folder's name was never shell text

    def dmp(self, command):
        """A `./vrrw dmp` command line of the README, run on this test's report folder (no shell)."""
        words = [re.sub(r'^\w+_report/', self.out + '/', w) for w in shlex.split(command)]  # the README's folder
        words = [os.path.join(self.out, w) if w.endswith(('.yaml', '.csv')) else w for w in words]  # beside it
        return subprocess.run([VRRW, *words[1:]], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              timeout=120)

    def test_the_readmes_dmp_example_runs_without_warnings(self):
        with open(os.path.join(ROOT, 'README.md')) as f:
            readme = f.read()
        block = re.search(r'becomes Dynamic Movement Primitives.*?```bash\n(.*?)```', readme, re.S).group(1)
        commands = [line.split('  #')[0].strip() for line in block.splitlines() if line.startswith('./vrrw dmp ')]
        self.assertEqual([c.split()[2] for c in commands], ['learn', 'rollout', 'plot'])
        for command in commands[:2]:
            result = self.dmp(command)
            print(result.stdout, result.stderr)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertNotIn('warning', result.stderr)
            self.assertNotIn('advice:', result.stdout)  # one instruction: the fit needs no advice
        with open(os.path.join(self.out, 'final.yaml')) as f:
            source = yaml.safe_load(f)['provenance']['source']
        self.assertRegex(source, '^' + re.escape(os.path.join(self.out, 'demonstration.bag')) +
                         r' robot ur5e segment final \d+\.\d{3}-\d+\.\d{3} s$')

    def test_learning_a_whole_demonstration_says_what_would_fit(self):
        # 20 basis functions for five motions with rests between them (the default 50 fits within 0.0106 rad,
        # at the advice's threshold of 0.01)
        result = self.dmp('./vrrw dmp learn --demo demo_report/demonstration.bag --robot ur5e --basis 20 '
                          '--out whole.yaml')
        self.assertEqual(result.returncode, 0, result.stderr)
        print(result.stdout)
        fit = float(re.search(r'reproduction RMSE ([0-9.e-]+) rad', result.stdout).group(1))
        self.assertGreater(fit, 0.02)  # 0.040-0.053 rad measured on three demonstrations
        self.assertLess(fit, 0.15)
        advice = [line for line in result.stdout.splitlines() if line.startswith('advice: ')]
        self.assertIn('with --segment NAME (this bag has near_pick pick close_gripper', advice[0])
        self.assertRegex(advice[-1], r'^advice: (--basis \d+ reproduces it within|no basis count up to 1000)')


class BadSceneTest(unittest.TestCase):
    def test_unknown_scene(self):
        result = demo('--scene', 'no_such_cell', '--quick', timeout=60)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn('no_such_cell', result.stderr)

    def test_scene_without_a_graspable_object(self):
        scene = os.path.join(tempfile.mkdtemp(prefix='vrrw_demo_bad_'), 'no_drill.yaml')
        with open(scene, 'w') as f:
            f.write('robots:\n  - {name: ur5e, model: ur5e, gripper: robotiq_2f_85, base: {xyz: [-0.35, 0, 0.75]}}\n'
                    'objects:\n  - {name: table, kind: table}\n')
        result = demo('--scene', scene, '--quick', timeout=60)
        self.assertNotEqual(result.returncode, 0)
        lines = [line for line in result.stderr.splitlines() if line.strip()]
        self.assertIn('no graspable object', lines[-1])
        self.assertIn('table (table, fixed)', lines[-1])
