set(vrrw_msgs_MESSAGE_FILES "msg/Event.msg")
set(vrrw_msgs_SERVICE_FILES "srv/ComputeFK.srv;srv/ComputeIK.srv;srv/CheckState.srv;srv/Plan.srv;srv/AttachObject.srv;srv/GhostSetJoints.srv;srv/GhostSetPose.srv;srv/GhostPreset.srv;srv/GhostPlan.srv;srv/GhostExecute.srv;srv/GhostSupportSurface.srv;srv/DemoStart.srv;srv/DemoStop.srv;srv/DemoAnnotate.srv")
