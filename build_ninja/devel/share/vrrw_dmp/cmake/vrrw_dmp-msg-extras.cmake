set(vrrw_dmp_MESSAGE_FILES "")
set(vrrw_dmp_SERVICE_FILES "/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Learn.srv;/work/wt/tools/catkin_ws/src/vrrw_dmp/srv/Plan.srv")
