set(vrrw_dmp_MESSAGE_FILES "")
set(vrrw_dmp_SERVICE_FILES "srv/Learn.srv;srv/Plan.srv")
