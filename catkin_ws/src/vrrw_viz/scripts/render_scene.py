#!/usr/bin/env python3
"""Brings a scene up headless under Xvfb with its own ROS master and saves one rviz frame.

  render_scene.py SCENE --out FILE.png [--width W] [--height H] [--timeout S] [--hide DISPLAY ...]
                  [--ghost ROBOT=PRESET ...]

--ghost starts the interaction node and poses that robot's ghost at a preset before the frame is taken.

Prints progress to stderr and, last, one JSON line: the output file, the seconds from launch
until the frame was taken, and the share of the 3D view that is not background.
"""
import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

import yaml

ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(os.path.dirname(__file__), '../../../..')))
BACKGROUND = (206, 212, 220)


def log(message):
    print(f'render: {message}', file=sys.stderr, flush=True)


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def free_display():
    for number in range(90, 200):
        if not os.path.exists(f'/tmp/.X{number}-lock') and not os.path.exists(f'/tmp/.X11-unix/X{number}'):
            return number
    raise RuntimeError('no free X display number between :90 and :199')


def render_config(path, width, height, hidden):
    """The shipped rviz config without panels, on a plain background, with the given displays off."""
    with open(os.path.join(ROOT, 'launch', 'vrrw.rviz')) as f:
        config = yaml.safe_load(f)
    config['Window Geometry'].update({'Width': width, 'Height': height, 'X': 0, 'Y': 0,
                                      'Hide Left Dock': True, 'Hide Right Dock': True})
    config['Panels'] = []
    manager = config['Visualization Manager']
    manager['Global Options']['Background Color'] = '; '.join(str(c) for c in BACKGROUND)
    for display in manager['Displays']:
        if display['Name'] in hidden:
            display['Enabled'] = False
            display['Value'] = False
    with open(path, 'w') as f:
        yaml.safe_dump(config, f)


def capture(display, path):
    subprocess.run(['import', '-display', f':{display}', '-window', 'root', path], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def view_pixels(path):
    """RGB rows of the 3D view: the capture without rviz's menu and tool bars and status bar."""
    import matplotlib.image
    import numpy
    image = matplotlib.image.imread(path)
    if image.ndim == 2:  # a uniform frame (rviz not drawn yet) is saved as grey
        image = numpy.stack([image] * 3, axis=2)
    image = (image[..., :3] * 255).astype('int16')
    return image[70:-40, :, :]


def background_distance(pixels):
    import numpy
    return numpy.abs(pixels - numpy.array(BACKGROUND, dtype='int16')).max(axis=2)


def foreground_share(pixels):
    return float((background_distance(pixels) > 40).mean())


def background_share(pixels):
    return float((background_distance(pixels) <= 8).mean())


def settled_frame(display, frame, start, timeout, still_seconds=1.0):
    """The 3D view once rviz has painted it (its background colour fills part of it) and it stayed the same
    for still_seconds: until the window is mapped the root window is uniformly black, and a frame that is
    merely unchanged for one capture interval may be that black root window or rviz blocked loading meshes."""
    still_since, previous = None, None
    while True:
        capture(display, frame)
        pixels = view_pixels(frame)
        painted = background_share(pixels) > 0.2
        same = previous is not None and previous.shape == pixels.shape and (abs(previous - pixels) > 8).mean() < 1e-4
        now = time.monotonic()
        still_since = (still_since or now) if painted and same else None
        if still_since is not None and now - still_since >= still_seconds:
            return pixels
        if now - start > timeout:
            why = 'stay still' if painted else 'paint its 3D view (background colour not on the screen)'
            sys.exit(f'render: rviz did not {why} within {timeout} s')
        previous = pixels
        time.sleep(0.25)


def wait_for_scene(timeout):
    """Until robot_description is set and tf holds every link of it."""
    import rospy
    import tf2_ros
    import xml.etree.ElementTree as ET
    rospy.init_node('vrrw_render', anonymous=True, disable_signals=True)
    deadline = time.monotonic() + timeout
    while not rospy.has_param('/robot_description'):
        if time.monotonic() > deadline:
            raise RuntimeError('robot_description never appeared (did the scene load? see the log above)')
        time.sleep(0.1)
    links = [link.get('name') for link in ET.fromstring(rospy.get_param('/robot_description')).iter('link')]
    buffer = tf2_ros.Buffer()
    tf2_ros.TransformListener(buffer)
    for link in links:
        remaining = max(0.1, deadline - time.monotonic())
        if not buffer.can_transform('world', link, rospy.Time(0), rospy.Duration(remaining)):
            raise RuntimeError(f'tf never held link {link}')
    return len(links)


def pose_ghost(spec, timeout):
    """ROBOT=PRESET: the robot's ghost at that preset, through the interaction node's service."""
    import rospy
    from vrrw_msgs.srv import GhostPreset
    robot, _, preset = spec.partition('=')
    if not robot or not preset:
        raise RuntimeError(f"'{spec}': expected ROBOT=PRESET")
    from vrrw_common.services import PersistentServices, ServiceCallError
    try:
        answer = PersistentServices(wait_seconds=timeout).call(f'/{robot}/ghost/preset', GhostPreset, preset)
    except ServiceCallError as error:
        raise RuntimeError(f"'{spec}': {error} (unknown robot?)")
    if not answer.success:
        raise RuntimeError(f"'{spec}': {answer.message}")
    time.sleep(0.5)  # the ghost frames reach rviz


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('scene')
    parser.add_argument('--out', required=True)
    parser.add_argument('--width', type=int, default=1280)
    parser.add_argument('--height', type=int, default=960)
    parser.add_argument('--timeout', type=float, default=30.0)
    parser.add_argument('--hide', nargs='*', default=[], help='rviz displays to turn off (e.g. Robots Objects)')
    parser.add_argument('--ghost', nargs='*', default=[], help='ROBOT=PRESET: pose a ghost (e.g. ur5e=square_left)')
    args = parser.parse_args()
    for tool in ('Xvfb', 'import', 'roslaunch'):
        if not shutil.which(tool):
            sys.exit(f'render: {tool} is not installed; run ./vrrw setup')

    workdir = tempfile.mkdtemp(prefix='vrrw_render_')
    config = os.path.join(workdir, 'render.rviz')
    # without the interaction node there are no ghost frames: rviz would pile every ghost link at the origin
    render_config(config, args.width, args.height, set(args.hide) | (set() if args.ghost else {'Ghosts'}))
    display = free_display()
    env = dict(os.environ, DISPLAY=f':{display}', ROS_MASTER_URI=f'http://127.0.0.1:{free_port()}')
    os.environ.update(env)
    processes = []
    try:
        processes.append(subprocess.Popen(['Xvfb', f':{display}', '-screen', '0', f'{args.width}x{args.height}x24',
                                           '-nolisten', 'tcp'], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                          start_new_session=True))
        start = time.monotonic()
        log(f'launching {args.scene} on display :{display}')
        launch_log = open(os.path.join(workdir, 'roslaunch.log'), 'w')
        processes.append(subprocess.Popen(['roslaunch', os.path.join(ROOT, 'launch', 'bringup.launch'),
                                           f'scene:={args.scene}', 'rviz:=true', f'rviz_config:={config}',
                                           f'interaction:={"true" if args.ghost else "false"}'],
                                          env=env, stdout=launch_log, stderr=subprocess.STDOUT,
                                          start_new_session=True))
        try:
            links = wait_for_scene(args.timeout)
        except RuntimeError as error:
            launch_log.flush()
            with open(launch_log.name) as f:
                sys.stderr.write(f.read()[-3000:])
            sys.exit(f'render: {error}')
        try:
            for ghost in args.ghost:
                pose_ghost(ghost, args.timeout)
        except RuntimeError as error:
            sys.exit(f'render: --ghost {error}')
        log(f'{links} links in tf after {time.monotonic() - start:.1f} s; waiting for a still frame')
        frame = os.path.join(workdir, 'frame.png')
        pixels = settled_frame(display, frame, start, args.timeout)
        seconds = time.monotonic() - start
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        shutil.copyfile(frame, args.out)
        log(f'wrote {args.out}')
        print(json.dumps({'out': args.out, 'seconds_to_frame': round(seconds, 2),
                          'foreground_share': round(foreground_share(pixels), 4)}))
    finally:
        for process in reversed(processes):
            try:
                os.killpg(process.pid, signal.SIGINT)
                process.wait(timeout=10)
            except (ProcessLookupError, subprocess.TimeoutExpired):
                os.killpg(process.pid, signal.SIGKILL)
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    main()
