#!/usr/bin/env python3
"""Saves one rviz frame of a scene, headless under Xvfb, as PNG.

  render_scene.py SCENE --out FILE.png [--ghost ROBOT=PRESET ...]     brings SCENE up on its own ROS master
  render_scene.py --running --out FILE.png                            the workspace running on $ROS_MASTER_URI
  common: [--camera iso|front|side|back|top | --view x,y,z,yaw,pitch] [--width W] [--height H] [--timeout S]
          [--hide DISPLAY ...]

The camera frames the robots (and their ghosts) and the scene's objects from their bounds in tf; --camera
names its direction, --view gives its focal point and direction (the distance still frames the scene).
Prints progress to stderr and, last, one JSON line: the output file, the seconds until the frame was taken,
the share of the 3D view that is not background, and the camera.
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

import render_camera

ROOT = os.environ.get('VRRW_ROOT', os.path.abspath(os.path.join(os.path.dirname(__file__), '../../../..')))
BACKGROUND = (206, 212, 220)
LINK_REACH = 0.1  # m around a link's frame its body may reach (the camera frames these boxes)


def log(message):
    print(f'render: {message}', file=sys.stderr, flush=True)


def refuse(message):
    """Bad input: one line, exit 2, nothing started."""
    print(f'render: {message}', file=sys.stderr, flush=True)
    sys.exit(2)


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def port_free(port):
    """Nothing listens on the port (a master that just ended leaves connections in TIME_WAIT: free, as for
    the next master, which binds with SO_REUSEADDR too)."""
    with socket.socket() as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(('127.0.0.1', port))
            return True
        except OSError:
            return False


def free_display():
    for number in range(90, 200):
        if not os.path.exists(f'/tmp/.X{number}-lock') and not os.path.exists(f'/tmp/.X11-unix/X{number}'):
            return number
    raise RuntimeError('no free X display number between :90 and :199')


def render_config(path, width, height, hidden, camera=None):
    """The shipped rviz config without panels, on a plain background, the given displays off, the camera
    (render_camera.fit) set, or the shipped one without it."""
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
    if camera:
        manager['Views']['Current'].update({'Distance': camera['distance'], 'Yaw': camera['yaw'],
                                            'Pitch': camera['pitch'], 'Field of View': render_camera.FIELD_OF_VIEW,
                                            'Focal Point': dict(zip('XYZ', camera['focal']))})
    with open(path, 'w') as f:
        yaml.safe_dump(config, f)


def capture(display, path):
    if subprocess.run(['import', '-display', f':{display}', '-window', 'root', path], stdout=subprocess.DEVNULL,
                      stderr=subprocess.DEVNULL).returncode != 0:
        raise RuntimeError(f'import could not capture display :{display}')


def start_display(processes, width, height, timeout=10.0):
    """An Xvfb screen of its own, once it accepts clients; its number."""
    display = free_display()
    processes.start(['Xvfb', f':{display}', '-screen', '0', f'{width}x{height}x24', '-nolisten', 'tcp'])
    deadline = time.monotonic() + timeout
    while not os.path.exists(f'/tmp/.X11-unix/X{display}'):
        if time.monotonic() > deadline:
            raise RuntimeError(f'Xvfb :{display} did not start within {timeout} s')
        time.sleep(0.05)
    return display


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


def settled_frame(display, frame, start, timeout, moving):
    """The 3D view once rviz has painted it (its background colour fills part of it) and it stayed the same for
    a second; a workspace that moves (`moving`) is taken 5 s after rviz painted, still or not. Until the window
    is mapped the root window is black, and a frame merely unchanged once may be rviz blocked loading meshes."""
    still_since, painted_since, previous = None, None, None
    while True:
        capture(display, frame)
        pixels = view_pixels(frame)
        painted = float((background_distance(pixels) <= 8).mean()) > 0.2
        same = previous is not None and previous.shape == pixels.shape and (abs(previous - pixels) > 8).mean() < 1e-4
        now = time.monotonic()
        painted_since = (painted_since or now) if painted else None
        still_since = (still_since or now) if painted and same else None
        if (still_since and now - still_since >= 1.0) or (moving and painted_since and now - painted_since >= 5.0):
            return pixels
        if now - start > timeout:
            why = 'stay still' if painted else 'paint its 3D view (background colour not on the screen)'
            raise RuntimeError(f'rviz did not {why} within {timeout} s')
        previous = pixels
        time.sleep(0.25)


def workspace_missing():
    """The running-workspace check every tool makes (vrrw_common's vrrw_workspace_check, 2 s at most): None when
    a workspace answers at $ROS_MASTER_URI, else its one line (`no workspace at ...: start one with ./vrrw up`)."""
    result = subprocess.run(['rosrun', 'vrrw_common', 'vrrw_workspace_check'], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=30)
    return None if result.returncode == 0 else (result.stdout.strip().splitlines() or ['no workspace'])[-1]


_TF = None


def tf_buffer():
    """This process's ROS node and tf listener, started on first use."""
    global _TF
    if _TF is None:
        import rospy
        import tf2_ros
        rospy.init_node('vrrw_render', anonymous=True, disable_signals=True)
        _TF = tf2_ros.Buffer()
        tf2_ros.TransformListener(_TF)
    return _TF


def has_param(name):
    """rospy.has_param, False while the master is still starting."""
    import rospy
    try:
        return rospy.has_param(name)
    except OSError:
        return False


def wait_for_description(timeout):
    """Until robot_description is set (wall clock); its links."""
    import rospy
    import xml.etree.ElementTree as ET
    deadline = time.monotonic() + timeout
    while not has_param('/robot_description'):
        if time.monotonic() > deadline:
            raise RuntimeError('robot_description never appeared (did the scene load? see the log above)')
        time.sleep(0.1)
    return [link.get('name') for link in ET.fromstring(rospy.get_param('/robot_description')).iter('link')]


def wait_for_scene(timeout):
    """Until robot_description is set and tf holds every link of it; the links. Waits on the wall clock: a
    paused simulation holds ROS time still."""
    import rospy
    deadline = time.monotonic() + timeout
    links = wait_for_description(timeout)
    tf = tf_buffer()  # after the master answers: rospy's node would warn it cannot register while it starts
    for link in links:
        while not tf.can_transform('world', link, rospy.Time(0)):
            if time.monotonic() > deadline:
                raise RuntimeError(f'tf never held link {link}')
            time.sleep(0.02)
    return links


def rotate(q, v):
    """Vector v turned by the unit quaternion q (x, y, z, w)."""
    x, y, z, w = q
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + y * tz - z * ty, v[1] + w * ty + z * tx - x * tz, v[2] + w * tz + x * ty - y * tx)


def in_world(frame, point):
    import rospy
    t = tf_buffer().lookup_transform('world', frame, rospy.Time(0), rospy.Duration(1.0)).transform
    turned = rotate((t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w), point)
    return tuple(turned[i] + (t.translation.x, t.translation.y, t.translation.z)[i] for i in range(3))


def scene_points(links, ghosts):
    """Corners of a box LINK_REACH around every link (and ghost link) and of every object's marker, in world."""
    import rospy
    from visualization_msgs.msg import MarkerArray
    points = []
    frames = links + ([f'ghost/{link}' for link in links] if ghosts else [])
    for frame in frames:
        try:
            centre = in_world(frame, (0.0, 0.0, 0.0))
        except Exception:  # a ghost frame may be missing (no ghost for that arm): it adds nothing
            continue
        points += render_camera.box_corners(tuple(c - LINK_REACH for c in centre), tuple(c + LINK_REACH for c in centre))
    try:
        markers = rospy.wait_for_message('/scene/objects', MarkerArray, timeout=3.0).markers
    except rospy.ROSException:
        markers = []
    for m in markers:
        half = tuple(max(s, 0.05) / 2 for s in (m.scale.x, m.scale.y, m.scale.z))
        q = (m.pose.orientation.x, m.pose.orientation.y, m.pose.orientation.z, m.pose.orientation.w or 1.0)
        for corner in render_camera.box_corners(tuple(-h for h in half), half):
            local = rotate(q, corner)
            local = tuple(local[i] + (m.pose.position.x, m.pose.position.y, m.pose.position.z)[i] for i in range(3))
            try:
                points.append(in_world(m.header.frame_id, local))
            except Exception:
                pass
    return points


def pose_ghost(spec, timeout):
    """ROBOT=PRESET: the robot's ghost at that preset, through the interaction node's service."""
    from vrrw_msgs.srv import GhostPreset
    robot, _, preset = spec.partition('=')
    from vrrw_common.services import PersistentServices, ServiceCallError
    try:
        answer = PersistentServices(wait_seconds=timeout).call(f'/{robot}/ghost/preset', GhostPreset, preset)
    except ServiceCallError as error:
        raise RuntimeError(f"--ghost '{spec}': {error} (unknown robot?)")
    if not answer.success:
        raise RuntimeError(f"--ghost '{spec}': {answer.message}")
    time.sleep(0.5)  # the ghost frames reach tf


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('scene', nargs='?', help='a shipped scene name or a scene YAML (not with --running)')
    parser.add_argument('--running', action='store_true', help='the workspace running on $ROS_MASTER_URI')
    parser.add_argument('--out', required=True)
    parser.add_argument('--camera', choices=sorted(render_camera.CAMERAS), help='direction of the framing camera')
    parser.add_argument('--view', help='x,y,z,yaw,pitch: focal point (m) and direction (rad)')
    parser.add_argument('--width', type=int, default=1280)
    parser.add_argument('--height', type=int, default=960)
    parser.add_argument('--timeout', type=float, default=30.0)
    parser.add_argument('--hide', nargs='*', default=[], help='rviz displays to turn off (e.g. Robots Objects)')
    parser.add_argument('--ghost', nargs='*', default=[], help='ROBOT=PRESET: pose a ghost (e.g. ur5e=square_left)')
    args = parser.parse_args(argv)
    if args.running == bool(args.scene):
        refuse('give a SCENE to bring up, or --running for the workspace on $ROS_MASTER_URI (not both)')
    if args.running and args.ghost:
        refuse('--ghost poses a ghost of a SCENE brought up here; --running shows the workspace as it is')
    if args.camera and args.view:
        refuse('--camera and --view both set the camera: give one')
    if args.view:
        try:
            args.view = render_camera.parse_view(args.view)
        except ValueError as error:
            refuse(f'--view {error}')
    for spec in args.ghost:
        if not all(spec.partition('=')[::2]):
            refuse(f"--ghost '{spec}': expected ROBOT=PRESET")
    if not (64 <= args.width <= 4096 and 64 <= args.height <= 4096):
        refuse(f'--width/--height {args.width}x{args.height}: each must be within 64..4096 pixels')
    if not 1.0 <= args.timeout <= 600.0:
        refuse(f'--timeout {args.timeout}: must be within 1..600 s')
    existing = os.path.dirname(os.path.abspath(args.out))
    while not os.path.isdir(existing):
        existing = os.path.dirname(existing)
    try:
        if os.path.isdir(args.out):
            raise OSError('a directory')
        tempfile.TemporaryFile(dir=existing).close()
    except OSError as error:
        refuse(f'--out {args.out}: cannot write a file there ({getattr(error, "strerror", None) or error})')
    for tool in ('Xvfb', 'import', 'roslaunch', 'rviz'):
        if not shutil.which(tool):
            refuse(f'{tool} is not installed; run ./vrrw setup')
    return args


class Processes:
    """What the render starts, each in its own session; stopped in reverse order on leaving (Ctrl-C too)."""

    def __init__(self):
        self.started = []

    def start(self, argv, log_file=None, env=None):
        out = log_file or subprocess.DEVNULL
        self.started.append(subprocess.Popen(argv, env=env, stdout=out, stderr=subprocess.STDOUT if log_file else out,
                                             start_new_session=True))
        return self.started[-1]

    def __enter__(self):
        return self

    def __exit__(self, *_):
        for process in reversed(self.started):
            try:
                os.killpg(process.pid, signal.SIGINT)
                process.wait(timeout=10)
            except (ProcessLookupError, subprocess.TimeoutExpired):
                try:
                    os.killpg(process.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass


def render(args, workdir, processes):
    import rospy
    start = time.monotonic()
    if args.running:
        missing = workspace_missing()
        if missing:
            print(f'render: {missing}', file=sys.stderr, flush=True)
            sys.exit(1)
    display = start_display(processes, args.width, args.height)  # (while the scene comes up)
    if not args.running:  # the scene on a master of its own; the interaction node (the ghosts) when asked for
        os.environ['ROS_MASTER_URI'] = f'http://127.0.0.1:{free_port()}'
        log(f'launching {args.scene}')
        processes.start(['roslaunch', os.path.join(ROOT, 'launch', 'bringup.launch'), f'scene:={args.scene}',
                         'rviz:=false', f'interaction:={"true" if args.ghost else "false"}'],
                        open(os.path.join(workdir, 'roslaunch.log'), 'w'))
    try:
        links = wait_for_scene(args.timeout)
        for ghost in args.ghost:
            pose_ghost(ghost, args.timeout)
    except RuntimeError:
        if not args.running:
            with open(os.path.join(workdir, 'roslaunch.log')) as f:
                sys.stderr.write(f.read()[-3000:])
        raise
    # without the interaction node there are no ghost frames: rviz would pile every ghost link at the origin
    ghosts = rospy.has_param('/ghost_description') and 'Ghosts' not in args.hide
    aspect = args.width / max(1, args.height - 110)  # the 3D view below the tool bar, above the status bar
    yaw, pitch = render_camera.CAMERAS[args.camera or 'iso']
    focal = None
    if args.view:
        focal, yaw, pitch = args.view
    camera = render_camera.fit(scene_points(links, ghosts), yaw, pitch, aspect, focal)
    log(f'{len(links)} links in tf after {time.monotonic() - start:.1f} s; camera on {camera["focal"]} from '
        f'{camera["distance"]:.2f} m; waiting for a still frame')
    config = os.path.join(workdir, 'render.rviz')
    render_config(config, args.width, args.height, set(args.hide) | (set() if ghosts else {'Ghosts'}), camera)
    processes.start(['rosrun', 'rviz', 'rviz', '-d', config], open(os.path.join(workdir, 'rviz.log'), 'w'),
                    dict(os.environ, DISPLAY=f':{display}'))
    frame = os.path.join(workdir, 'frame.png')
    pixels = settled_frame(display, frame, time.monotonic(), args.timeout, moving=args.running)
    seconds = time.monotonic() - start
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    shutil.copyfile(frame, args.out)
    log(f'wrote {args.out}')
    camera['focal'] = [round(c, 3) for c in camera['focal']]
    camera['distance'] = round(camera['distance'], 3)
    print(json.dumps({'out': args.out, 'seconds_to_frame': round(seconds, 2),
                      'foreground_share': round(foreground_share(pixels), 4), 'camera': camera}))


def main():
    args = parse(sys.argv[1:])
    workdir = tempfile.mkdtemp(prefix='vrrw_render_')
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))  # leave through the cleanup below
    try:
        with Processes() as processes:
            render(args, workdir, processes)
    except RuntimeError as error:
        print(f'render: {error}', file=sys.stderr, flush=True)
        sys.exit(1)
    except KeyboardInterrupt:
        sys.exit(130)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    main()
