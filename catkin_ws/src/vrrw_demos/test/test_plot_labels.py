#!/usr/bin/python3
"""demos plot: the segment names stand apart (no two overlap), above the joints' axes and below the title, also
where a short gripper action sits between two motions. The segments are those of ./vrrw demo --quick's
demonstration (vrrw demos segment), plus a crowded case of six instructions within 1.2 s of a 12 s demonstration."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'scripts'))
import plot_demo  # noqa: E402

DEMO = [('near_pick', 0.43, 3.43), ('pick', 3.43, 4.92), ('close_gripper', 5.22, 5.55),
        ('back_to_near_pick', 5.55, 7.05), ('final', 7.05, 12.4), ('open_gripper', 12.55, 12.84)]
CROWDED = [(name, 0.2 * k, 0.2 * k + 0.15) for k, name in
           enumerate(['near_pick', 'pick', 'close_gripper', 'back_to_near_pick', 'final', 'open_gripper'])]


def figure(segments, end=13.0, title='demo_report/demonstration.bag (ur5e)'):
    data = [[0.01 * k, 0.1, -1.5, 1.4, -1.4, -1.57, 0.2] + [0.0] * 6 + [0.1] for k in range(int(end * 100))]
    header = ['t'] + [f'q{j}' for j in range(1, 7)] + [f'q{j}_vel' for j in range(1, 7)] + ['gripper']
    fig, texts = plot_demo.draw(data, header, [{'name': n, 'start': s, 'end': e} for n, s, e in segments], title)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    return fig, [t.get_window_extent(renderer) for t in texts], renderer


class SegmentLabels(unittest.TestCase):
    def check(self, segments, rows):
        fig, boxes, renderer = figure(segments)
        self.assertEqual(len(boxes), len(segments))
        for a in range(len(boxes)):
            for b in range(a + 1, len(boxes)):
                self.assertFalse(boxes[a].overlaps(boxes[b]), f'{segments[a][0]} and {segments[b][0]} overlap: '
                                                              f'{boxes[a]} {boxes[b]}')
        axes_top = fig.axes[0].get_window_extent(renderer).y1
        title_bottom = fig._suptitle.get_window_extent(renderer).y0
        for (name, _, _), box in zip(segments, boxes):
            self.assertGreaterEqual(box.y0, axes_top, name)  # above the joints' axes
            self.assertLessEqual(box.y1, title_bottom, name)  # below the title
        self.assertEqual(len({round(box.y0) for box in boxes}), rows)

    def test_the_demonstrations_names_stand_apart(self):
        self.check(DEMO, rows=2)  # close_gripper next to back_to_near_pick takes a second row

    def test_six_instructions_in_a_second(self):
        self.check(CROWDED, rows=4)


if __name__ == '__main__':
    unittest.main()
