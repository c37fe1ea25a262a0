"""What the teaching tests share: a workspace of their own brought up as a user does (./vrrw up, with its
recorder), a scripted teacher from outside, and the check of a skill's segments against where the teacher acted."""
import json
import os
import signal
import socket
import subprocess
import tempfile
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '../../../..'))
VRRW = os.path.join(ROOT, 'vrrw')


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def wait_for_service(service, seconds):
    """Until the workspace offers service (it is up), or fail."""
    import rosgraph
    master = rosgraph.Master('/test_teach_box')
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        try:
            master.lookupService(service)
            return
        except Exception:  # no master yet, or no such service yet
            time.sleep(1.0)
    raise AssertionError(f'{service}: not offered within {seconds} s')


def run(arguments, timeout):
    return subprocess.run([VRRW] + arguments, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=timeout)


def stop(process):
    if process.poll() is None:
        os.killpg(process.pid, signal.SIGINT)
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)


def teach(scene, teacher_arguments, name):
    """Brings scene up in physics (its recorder with it) on a master of its own (ROS_MASTER_URI of this process),
    lets scripted_teacher.py teach with teacher_arguments, and returns (folder, bag, truth, processes running)."""
    folder = tempfile.mkdtemp(prefix=f'vrrw_teach_{name}_')
    bag, truth = os.path.join(folder, name + '.bag'), os.path.join(folder, 'truth.json')
    os.environ['ROS_MASTER_URI'] = f'http://localhost:{free_port()}'
    os.environ['VRRW_ROS_PORT'] = str(free_port())  # skill evaluate's own master
    processes = []
    try:
        with open(os.path.join(folder, 'workspace.log'), 'w') as log:
            # every ./vrrw up runs the workspace's recorder, idle until /demos/start
            processes.append(subprocess.Popen([VRRW, 'up', scene, '--mode', 'physics'], stdout=log,
                                              stderr=subprocess.STDOUT, start_new_session=True))
            for service in ('/ur5e/ghost/execute', '/demos/start'):
                wait_for_service(service, 120.0)
        teacher = subprocess.run(['/usr/bin/python3', os.path.join(HERE, 'scripted_teacher.py'), '--truth', truth,
                                  '--bag', bag] + teacher_arguments, timeout=400)
        assert teacher.returncode == 0, 'the scripted teacher failed'
    except BaseException:
        for process in reversed(processes):
            stop(process)
        raise
    return folder, bag, truth, processes


def segment_errors(skill_file, truth_file):
    """Per instruction (start error, end error), s: the skill's segments against the teacher's actions (from the
    first action's start to the last action's end of each instruction)."""
    with open(skill_file) as f:
        source = yaml.safe_load(f)['sources'][0]
    with open(truth_file) as f:
        actions = json.load(f)['actions']
    spans = {}
    for action in actions:
        start, end = action['start'] - source['start_stamp'], action['end'] - source['start_stamp']
        spans[action['action']] = (spans.get(action['action'], (start, end))[0], end)
    found = {segment['name']: (segment['start'], segment['end']) for segment in source['segments']}
    assert set(found) == set(spans), f'found {sorted(found)}, the teacher did {sorted(spans)}'
    return {name: (found[name][0] - start, found[name][1] - end) for name, (start, end) in spans.items()}
