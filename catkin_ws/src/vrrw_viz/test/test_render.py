"""A headless render of the paper's multi-robot scene shows the robots; ./vrrw view without a display says to
render instead."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import matplotlib.image
import numpy

SCRIPT = os.path.join(os.path.dirname(__file__), '..', 'scripts', 'render_scene.py')
VRRW = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'vrrw')


def render(scene, out, *extra):
    result = subprocess.run([sys.executable, SCRIPT, scene, '--out', out, *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    return json.loads(result.stdout.strip().splitlines()[-1])


class RenderTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix='vrrw_render_test_')
        cls.full = render('paper_multibot', os.path.join(cls.dir, 'full.png'))
        cls.empty = render('paper_multibot', os.path.join(cls.dir, 'no_robots.png'), '--hide', 'Robots')

    def test_image_is_not_blank(self):
        print(f'frame after {self.full["seconds_to_frame"]} s')  # (a wall-clock figure: stated, not asserted)
        image = matplotlib.image.imread(self.full['out'])
        self.assertEqual(image.shape[:2], (960, 1280))
        self.assertGreater(float(image[..., :3].std()), 0.05)

    def test_robots_cover_a_plausible_area(self):
        # Robot pixels: where the frame differs from the same view with the robot display off.
        full = matplotlib.image.imread(self.full['out'])[..., :3]
        empty = matplotlib.image.imread(self.empty['out'])[..., :3]
        robot_share = float((numpy.abs(full - empty).max(axis=2) > 0.1).mean())
        print(f'robot pixels: {robot_share:.3f} of the frame')
        self.assertGreater(robot_share, 0.03)  # 0.082 measured with the framing camera
        self.assertLess(robot_share, 0.25)


class ViewTest(unittest.TestCase):
    def test_view_without_a_display_says_to_render(self):
        for display in ({}, {'DISPLAY': ':199'}):  # none, and one that is not running
            env = {k: v for k, v in os.environ.items() if k != 'DISPLAY'}
            result = subprocess.run([VRRW, 'view', 'pick_place_drill'], env=dict(env, **display), stdout=subprocess.PIPE,
                                    stderr=subprocess.PIPE, text=True, timeout=60)
            self.assertEqual(result.returncode, 2, result.stderr)
            self.assertTrue(result.stderr.startswith('vrrw: view: no display: use ./vrrw render'), result.stderr)
            self.assertNotIn('ready:', result.stdout)
