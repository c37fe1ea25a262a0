execute_process(COMMAND "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_common/catkin_generated/python_distutils_install.sh" RESULT_VARIABLE res)

if(NOT res EQUAL 0)
  message(FATAL_ERROR "execute_process(/work/wt/tools/build_ninja/catkin_ws/src/vrrw_common/catkin_generated/python_distutils_install.sh) returned error code ")
endif()
