#!/usr/bin/python3
"""The rospy helper: persistent calls, a missing service named, a failed call named and the next one reopened."""
import unittest

import rospy
import rostest
from std_srvs.srv import Trigger, TriggerResponse

from vrrw_common.services import PersistentServices, ServiceCallError


class Counter:
    def __init__(self, name):
        self.calls = 0
        self.persistent = 0
        self.failing = False
        self.server = rospy.Service(name, Trigger, self.answer)

    def answer(self, request):
        if self.failing:
            raise RuntimeError('out of order')
        self.calls += 1
        self.persistent += request._connection_header.get('persistent') == '1'
        return TriggerResponse(success=True, message=str(self.calls))


class TestRospyServices(unittest.TestCase):
    def test_calls_are_persistent(self):
        counter = Counter('/counted')
        services = PersistentServices()
        answers = [services.call('/counted', Trigger).message for _ in range(50)]
        self.assertEqual(answers, [str(i) for i in range(1, 51)])
        self.assertEqual(counter.persistent, 50)
        services.close()
        counter.server.shutdown()

    def test_missing_service_is_named(self):
        with self.assertRaises(ServiceCallError) as raised:
            PersistentServices(wait_seconds=0.3).call('/nothing', Trigger)
        self.assertEqual(str(raised.exception), '/nothing: no such service after 0.3 s')

    def test_a_failed_call_is_named_and_the_next_reopens(self):
        services = PersistentServices(wait_seconds=0.3)
        counter = Counter('/failing')
        self.assertEqual(services.call('/failing', Trigger).message, '1')
        counter.failing = True
        with self.assertRaises(ServiceCallError) as raised:
            services.call('/failing', Trigger)
        self.assertTrue(str(raised.exception).startswith('/failing: the call failed: '), str(raised.exception))
        self.assertIn('out of order', str(raised.exception))
        counter.failing = False
        self.assertEqual(services.call('/failing', Trigger).message, '2')
        self.assertEqual(counter.persistent, 2)
        counter.server.shutdown()


if __name__ == '__main__':
    rospy.init_node('test_rospy_services')
    rostest.rosrun('vrrw_common', 'rospy_services', TestRospyServices)
