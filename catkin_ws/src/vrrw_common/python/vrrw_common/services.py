"""Service calls from rospy over persistent connections.

A one-shot call's connection is closed by the server after it answers; ROS 1.15 may take that close for a
dead link before the answer is read (ros_comm#1976). A persistent connection is never closed by the server.
"""
import rospy


class ServiceCallError(RuntimeError):
    """A call that did not come back; str() is one line naming the service."""


class PersistentServices:
    """One persistent rospy.ServiceProxy per service name, opened at its first call, reopened after a drop."""

    def __init__(self, wait_seconds=5.0):
        self._wait_seconds = wait_seconds
        self._proxies = {}

    def call(self, name, service_class, *args, **kwargs):
        """Calls `name` with the request's fields; returns the response or raises ServiceCallError."""
        proxy = self._proxies.get(name)
        if proxy is None:
            try:
                rospy.wait_for_service(name, self._wait_seconds)
            except rospy.ROSException:
                raise ServiceCallError(f'{name}: no such service after {self._wait_seconds:g} s') from None
            proxy = self._proxies[name] = rospy.ServiceProxy(name, service_class, persistent=True)
        try:
            return proxy(*args, **kwargs)
        except (rospy.ServiceException, rospy.ROSException) as error:
            proxy.close()
            del self._proxies[name]
            raise ServiceCallError(f'{name}: the call failed: {error}') from None

    def close(self):
        for proxy in self._proxies.values():
            proxy.close()
        self._proxies.clear()
