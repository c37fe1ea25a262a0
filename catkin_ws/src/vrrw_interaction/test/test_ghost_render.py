"""A headless render of pick_place_drill with the UR5e's ghost posed at home (upright) shows both the robot
and its ghost: pixels that change when either display is hidden."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import matplotlib.image
import numpy

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..', '..', '..'))
SCRIPT = os.path.join(ROOT, 'catkin_ws', 'src', 'vrrw_viz', 'scripts', 'render_scene.py')


def render(out, *extra):
    result = subprocess.run([sys.executable, SCRIPT, 'pick_place_drill', '--out', out, '--ghost', 'ur5e=home',
                             '--width', '640', '--height', '480', *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=180)
    assert result.returncode == 0, result.stderr[-2000:]
    return matplotlib.image.imread(json.loads(result.stdout.strip().splitlines()[-1])['out'])[..., :3]


def share(a, b):
    # the ghost is drawn at alpha 0.4: against the light background it changes pixels by less than 0.1
    return float((numpy.abs(a - b).max(axis=2) > 0.03).mean())


class GhostRenderTest(unittest.TestCase):
    def test_robot_and_ghost_both_show(self):
        directory = tempfile.mkdtemp(prefix='vrrw_ghost_render_')
        full = render(os.path.join(directory, 'full.png'))
        no_ghost = render(os.path.join(directory, 'no_ghost.png'), '--hide', 'Ghosts')
        no_robot = render(os.path.join(directory, 'no_robot.png'), '--hide', 'Robots')
        ghost, robot = share(full, no_ghost), share(full, no_robot)
        print(f'ghost pixels {ghost:.4f}, robot pixels {robot:.4f} of the frame')
        self.assertGreater(ghost, 0.002)  # 0.0056 measured at 640x480
        self.assertGreater(robot, 0.004)  # 0.0109 measured
