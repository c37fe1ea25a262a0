set(vrrw_physics_MESSAGE_FILES "msg/Contact.msg;msg/Contacts.msg;msg/Hand.msg;msg/SpringTarget.msg")
set(vrrw_physics_SERVICE_FILES "srv/SetMode.srv;srv/SetGains.srv;srv/SetSpring.srv;srv/SetObjectPose.srv")
