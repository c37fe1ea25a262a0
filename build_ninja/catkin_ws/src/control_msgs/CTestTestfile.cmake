# CMake generated Testfile for 
# Source directory: /work/wt/tools/catkin_ws/src/control_msgs
# Build directory: /work/wt/tools/build_ninja/catkin_ws/src/control_msgs
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test(_ctest_control_msgs_gtest_test_md5sums "/work/wt/tools/build_ninja/catkin_generated/env_cached.sh" "/usr/bin/python3" "/usr/share/catkin/cmake/test/run_tests.py" "/work/wt/tools/build_ninja/test_results/control_msgs/gtest-test_md5sums.xml" "--return-code" "/work/wt/tools/build_ninja/devel/lib/control_msgs/test_md5sums --gtest_output=xml:/work/wt/tools/build_ninja/test_results/control_msgs/gtest-test_md5sums.xml")
set_tests_properties(_ctest_control_msgs_gtest_test_md5sums PROPERTIES  _BACKTRACE_TRIPLES "/usr/share/catkin/cmake/test/tests.cmake;160;add_test;/usr/share/catkin/cmake/test/gtest.cmake;98;catkin_run_tests_target;/usr/share/catkin/cmake/test/gtest.cmake;37;_catkin_add_google_test;/work/wt/tools/catkin_ws/src/control_msgs/CMakeLists.txt;14;catkin_add_gtest;/work/wt/tools/catkin_ws/src/control_msgs/CMakeLists.txt;0;")
