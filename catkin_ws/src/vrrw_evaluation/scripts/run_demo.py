#!/usr/bin/env python3
"""./vrrw demo: the paper's evaluation end to end, headless, with its own master under Xvfb.

  run_demo.py --launch WORKSPACE.launch --scene S [--trials N] [--seed S] [--out DIR] [--quick] [--arms A,B]
              [--rtf max|N] [--real NS [--yes]]

Brings the workspace up in physics mode (paused, at real-time factor --rtf: max by default) with rviz on a private
display, runs demo_runner (it holds the simulation and steps it through every motion: lockstep; teach,
segment, replay, generalize: the skill learned from the bag and its trials; it saves rviz frames at the
instruction boundaries), then draws the plots and frame strips beside the runner's metrics.json, report.md and
index.html. With --arms, the same trials of the same skill on each of those arms at the taught arm's base
(`./vrrw skill evaluate` on a copy of the scene), side by side in the report. With --real NS, stage 5
relays the demonstration to the real robot whose driver runs under NS on $ROS_MASTER_URI (demo_relay).
"""
import argparse
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(HERE, '../../../..')))
sys.path.insert(0, os.path.join(ROOT, 'catkin_ws', 'src', 'vrrw_viz', 'scripts'))
import render_scene  # noqa: E402  (the render's Xvfb, port and rviz config helpers)
import plot_demo  # noqa: E402

WIDTH, HEIGHT = 640, 520
# Closer than the shipped view: robot, drill, its final place and the bin fill the frame.
VIEW = {'Distance': 1.75, 'Focal Point': {'X': -0.02, 'Y': 0.05, 'Z': 0.82}, 'Pitch': 0.62, 'Yaw': 0.45}


def log(message):
    print(f'demo: {message}', flush=True)


# ur_robot_driver's trajectory action and joint states, under the driver's namespace
DRIVER_ACTION, DRIVER_STATES = 'scaled_pos_joint_traj_controller/follow_joint_trajectory', 'joint_states'


def runner_path(name='demo_runner'):
    for directory in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
        path = os.path.join(directory, 'lib', 'vrrw_evaluation', name)
        if os.access(path, os.X_OK):
            return path
    sys.exit(f'demo: {name} is not built: run ./vrrw build')


def driver_names(namespace):
    base = '/' + namespace.strip('/') if namespace.strip('/') else ''
    return f'{base}/{DRIVER_ACTION}', f'{base}/{DRIVER_STATES}'


def check_driver(master_uri, namespace):
    """--real: the robot's master answers and a driver serves its trajectory action there (before any stage
    runs); one line naming what is missing otherwise."""
    if not master_uri:
        sys.exit('demo: --real: ROS_MASTER_URI is not set (the master the robot driver runs on)')
    import rosgraph
    action, _ = driver_names(namespace)
    try:
        topics = {name for name, _ in rosgraph.Master('/vrrw_demo', master_uri=master_uri).getPublishedTopics('')}
    except Exception as error:  # refused, unreachable, not a master
        sys.exit(f'demo: --real: no ROS master at {master_uri} ({error})')
    if action + '/status' not in topics:
        sys.exit(f'demo: --real {namespace}: no driver action {action} on {master_uri} (nothing publishes its status)')


def relay(args, robot, master_uri, out):
    """Stage 5: a vrrw controller in real mode beside the driver, then demo_relay through it."""
    action, states = driver_names(args.real)
    env = dict(os.environ, ROS_MASTER_URI=master_uri)
    log(f'5 relay to {action} on {master_uri} ...')
    with open(os.path.join(out, 'relay_controller.log'), 'w') as f:
        controller = subprocess.Popen(['roslaunch', 'vrrw_control', 'controller.launch', f'robot:={robot}',
                                       f'scene:={args.scene}', 'mode:=real', f'real_driver_action:={action}',
                                       f'real_joint_states:={states}', 'publish_global_joint_states:=false'],
                                      env=env, stdout=f, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        return subprocess.run([runner_path('demo_relay'), '--scene', args.scene, '--bag',
                               os.path.join(out, 'demonstration.bag'), '--out', os.path.join(out, 'relay.json')]
                              + (['--yes'] if args.yes else []), env=env).returncode
    finally:
        stop([controller])


def arm_scene(scene, robot, arm, folder):
    """A copy of the scene with `arm` (a model of urdf/models.yaml) where the taught robot stands, named after
    the model: the skill's Cartesian keyframes and paths carry over, IK is the new arm's."""
    import yaml
    path = scene if os.path.isfile(scene) else os.path.join(ROOT, 'urdf', 'scenes', scene + '.yaml')
    with open(path) as f:
        cell = yaml.safe_load(f)
    for entry in cell['robots']:
        if entry['name'] == robot:
            entry['name'], entry['model'] = arm, arm
    cell['name'] = f"{cell.get('name', 'cell')}_{arm}"
    os.makedirs(folder, exist_ok=True)
    copy = os.path.join(folder, 'scene.yaml')
    with open(copy, 'w') as f:
        yaml.safe_dump(cell, f, sort_keys=False)
    return copy


def other_arms(args, robot, trials, out):
    """--arms: `skill evaluate` of the demo's skill on each arm; its figures into metrics.json and index.html."""
    results = {}
    for arm in [a for a in args.arms.split(',') if a]:
        folder = os.path.join(out, 'arms', arm)
        scene = arm_scene(args.scene, robot, arm, folder)
        log(f'arms: {arm} at the {robot}\'s base, {trials} trials (skill evaluate, log in {folder})')
        result = subprocess.run([os.path.join(ROOT, 'vrrw'), 'skill', 'evaluate', os.path.join(out, 'skill.yaml'),
                                 '--scene', scene, '--robot', arm, '--trials', str(trials), '--seed', str(args.seed),
                                 '--out', folder, '--rtf', args.rtf], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        with open(os.path.join(folder, 'evaluate.log'), 'w') as f:
            f.write(result.stdout)
        try:
            with open(os.path.join(folder, 'metrics.json')) as f:
                metrics = json.load(f)
        except (OSError, ValueError):
            log(f'arms: {arm}: skill evaluate failed (exit {result.returncode}; see {folder}/evaluate.log)')
            continue
        results[arm] = {key: metrics[key] for key in ('success_rate', 'reachable_rate', 'mean_cycle_seconds',
                                                      'mean_planning_ms', 'failures', 'trials')}
        log(f"arms: {arm}: {metrics['successes']} of {metrics['trials']} succeeded")
    with open(os.path.join(out, 'metrics.json')) as f:
        report = json.load(f)
    dmp = report['dmp']
    cycles = [t['cycle_seconds'] for t in dmp['trial_results'] if t['success']]
    results = {robot: {'success_rate': dmp['success_rate'], 'mean_cycle_seconds': sum(cycles) / max(len(cycles), 1),
                       'failures': dmp['failures'], 'trials': dmp['trials'], 'taught': True}, **results}
    report['arms'] = results
    with open(os.path.join(out, 'metrics.json'), 'w') as f:
        json.dump(report, f, indent=1)
    rows = ''.join(f"<tr><td>{arm}</td><td>{100 * r['success_rate']:.0f} % of {r['trials']}</td>"
                   f"<td>{r['mean_cycle_seconds']:.1f} s</td><td>{'; '.join(x['reason'] for x in r['failures'])}</td></tr>\n"
                   for arm, r in results.items())
    table = ('<h2>The skill on other arms at the same base</h2>\n<table>\n<tr><th>arm</th><th>success</th>'
             f'<th>mean cycle</th><th>why trials failed</th></tr>\n{rows}</table>\n')
    with open(os.path.join(out, 'index.html')) as f:
        html = f.read()
    with open(os.path.join(out, 'index.html'), 'w') as f:
        f.write(html.replace('</body>', table + '</body>'))


def stop(processes):
    for process in reversed(processes):
        try:
            os.killpg(process.pid, signal.SIGINT)
            process.wait(timeout=15)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def workspace_trouble(path, lines=12):
    """The workspace log's last errors, warnings and dead processes: what a failed run is first asked."""
    marks = ('process has died', '[ERROR]', '[FATAL]', '[ WARN]', 'terminate called', 'Segmentation fault',
             'Exception thrown')
    try:
        with open(path, errors='replace') as f:
            found = [line.rstrip() for line in f if any(mark in line for mark in marks)]
    except OSError:
        return []
    return [re.sub(r'\x1b\[[0-9;]*m', '', line) for line in found[-lines:]]


def demo_config(path):
    """The render's rviz config with the demo's view, drawn at 10 Hz (llvmpipe shares the 2 cores). The ghost
    and the markers are off: they would hide the drill, and the ghost stays where the teach left it."""
    import yaml
    render_scene.render_config(path, WIDTH, HEIGHT, {'Ghosts', 'Ghost markers', 'Free-drive markers'})
    with open(path) as f:
        config = yaml.safe_load(f)
    manager = config['Visualization Manager']
    manager['Views']['Current'].update(VIEW)
    manager['Global Options']['Frame Rate'] = 10
    with open(path, 'w') as f:
        yaml.safe_dump(config, f)


def parse_args(argv):
    """The command line; args.trials as given, else 3 with --quick and 20 without (an explicit option beats
    the preset)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--launch', required=True)
    parser.add_argument('--scene', default='pick_place_drill')
    parser.add_argument('--trials', type=int, help='DMP trials (default 20; 3 with --quick)')
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--out', default='demo_report')
    parser.add_argument('--quick', action='store_true', help='3 trials unless --trials says otherwise')
    parser.add_argument('--arms', default='', help='models to try the skill on at the taught arm\'s base, e.g. ur10e,ur3e')
    parser.add_argument('--rtf', default='max', help="physics' real-time factor: max (lockstep as fast as the cores "
                        "allow, the default) or a positive number (1: paced at real time)")
    parser.add_argument('--real', metavar='NS', help="relay to the real robot whose driver runs under NS")
    parser.add_argument('--yes', action='store_true', help='--real without asking')
    args = parser.parse_args(argv)
    if not re.fullmatch(r'max|(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?', args.rtf) or (args.rtf != 'max' and float(args.rtf) <= 0):
        parser.error(f"--rtf: '{args.rtf}' is not max or a positive number (the real-time factor; 1: paced at real time)")
    if args.trials is None:
        args.trials = 3 if args.quick else 20
    return args


def pinned(name, allowed, example):
    """The number an environment variable pins (VRRW_DISPLAY: 64 or :64; VRRW_ROS_PORT: 11311), None when unset;
    anything else ends the demo with one line before it touches anything."""
    text = os.environ.get(name, '')
    if not text:
        return None
    match = re.fullmatch(allowed, text)
    if not match:
        refuse(f"{name}: '{text}' is not {example}")
    return int(match.group(1))


def refuse(line):
    """Bad input: one line, exit 2, nothing touched."""
    print(f'demo: {line}', file=sys.stderr)
    sys.exit(2)


def main():
    args = parse_args(sys.argv[1:])
    # VRRW_DISPLAY / VRRW_ROS_PORT pin the display and the master's port (parallel runs on one machine).
    display = pinned('VRRW_DISPLAY', r':?(\d{1,4})', 'an X display number (64 or :64)')
    port = pinned('VRRW_ROS_PORT', r'(\d{1,5})', 'a port number (11311)')
    if port is not None and not 0 < port < 65536:
        refuse(f'VRRW_ROS_PORT: {port} is not a port number (1-65535)')
    if port is not None and not render_scene.port_free(port):
        # the demo's workspace is its own: a master already there (the user's workspace) would get a second set
        # of nodes, which replace the running ones by name
        refuse(f'VRRW_ROS_PORT: port {port} is in use (a running workspace?); demo starts its own: '
               'unset it or choose a free port')
    trials = args.trials
    robot_master = os.environ.get('ROS_MASTER_URI', '')
    if args.real is not None:
        check_driver(robot_master, args.real)
    elif args.yes:
        sys.exit('demo: --yes confirms --real NS, which was not given')
    for tool in ('Xvfb', 'import', 'roslaunch'):
        if not shutil.which(tool):
            sys.exit(f'demo: {tool} is not installed; run ./vrrw setup')
    runner = runner_path()
    checked = subprocess.run([runner, '--scene', args.scene, '--check'], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    if checked.returncode != 0:
        sys.exit(checked.stderr.strip() or f'demo: {args.scene}: not usable')
    log(checked.stdout.strip().replace('demo: ', ''))
    out = os.path.abspath(args.out)
    # an earlier report in the same folder leaves nothing behind: its frames and data files (a 20-trial run's
    # trial_3..19 beside a --quick run's metrics) go; other files in the folder are not the demo's and stay
    if os.path.isdir(os.path.join(out, 'frames')):
        shutil.rmtree(os.path.join(out, 'frames'))
    for old in glob.glob(os.path.join(out, 'data', '*.csv')):
        if re.fullmatch(r'(demonstration|replay|trial_\d+)_(joints|segments|track)\.csv', os.path.basename(old)):
            os.remove(old)
    os.makedirs(out, exist_ok=True)

    start = time.monotonic()
    workdir = tempfile.mkdtemp(prefix='vrrw_demo_')
    config = os.path.join(workdir, 'demo.rviz')
    # The workspace launch runs every node on the physics node's simulated time (controllers inside it, in
    # lockstep); the demonstration is recorded at 100 Hz of simulated time (a viewer gets 50 Hz). Physics starts
    # paused: the runner steps it through every motion, at --rtf.
    launch = os.path.join(workdir, 'demo.launch')
    with open(launch, 'w') as f:
        # the workspace's launch runs vrrw_demos' recorder, the demonstration's one bag writer
        f.write(f'<launch>\n  <include file="{args.launch}"/>\n'
                f'  <param name="/physics/publish_rate" value="100"/>\n  <param name="/physics/paused" value="true"/>\n'
                f'  <param name="/physics/rtf" value="{args.rtf}"/>\n</launch>\n')
    demo_config(config)
    display = display if display is not None else render_scene.free_display()
    port = port if port is not None else render_scene.free_port()
    env = dict(os.environ, DISPLAY=f':{display}', ROS_MASTER_URI=f'http://127.0.0.1:{port}')
    os.environ.update(env)
    processes = []
    launch_log = os.path.join(out, 'workspace.log')
    try:
        processes.append(subprocess.Popen(['Xvfb', f':{display}', '-screen', '0', f'{WIDTH}x{HEIGHT}x24', '-nolisten',
                                           'tcp'], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                          start_new_session=True))
        log(f'[0/4] bringing up {args.scene} in physics mode on display :{display} (log: {launch_log})')
        with open(launch_log, 'w') as f:
            processes.append(subprocess.Popen(['roslaunch', launch], env=env, stdout=f, stderr=subprocess.STDOUT,
                                              start_new_session=True))
            processes.append(subprocess.Popen(['rviz', '-d', config], env=env, stdout=f, stderr=subprocess.STDOUT,
                                              start_new_session=True))
        try:
            # the description only: physics waits paused, so tf has the robot once the runner's first step published it
            render_scene.wait_for_description(60.0)
        except RuntimeError as error:
            sys.exit(f'demo: {error} (see {launch_log})')
        log(f'workspace up after {time.monotonic() - start:.1f} s')
        capture = f'import -display :{display} -window root {{file}}'
        result = subprocess.run([runner, '--scene', args.scene, '--trials', str(trials), '--seed', str(args.seed),
                                 '--out', out, '--shown', '1' if args.quick else '2', '--capture', capture], env=env)
    finally:
        stop(processes)
        shutil.rmtree(workdir, ignore_errors=True)
    log('drawing plots and frame strips')
    plot_demo.draw(out)
    log(f'report: {os.path.join(out, "index.html")} ({time.monotonic() - start:.0f} s in all)')
    if result.returncode != 0:
        for line in workspace_trouble(launch_log):
            print(f'demo: workspace.log: {line}', file=sys.stderr)
        sys.exit(result.returncode)
    robot = re.search(r'robot (\S+) picks', checked.stdout).group(1)
    if args.arms:
        other_arms(args, robot, trials, out)
    if args.real is not None:
        sys.exit(relay(args, robot, robot_master, out))


if __name__ == '__main__':
    main()
