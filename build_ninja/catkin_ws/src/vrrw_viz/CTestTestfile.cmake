# CMake generated Testfile for 
# Source directory: /work/wt/tools/catkin_ws/src/vrrw_viz
# Build directory: /work/wt/tools/build_ninja/catkin_ws/src/vrrw_viz
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
add_test(_ctest_vrrw_viz_nosetests_test.test_render.py "/work/wt/tools/build_ninja/catkin_generated/env_cached.sh" "/usr/bin/python3" "/usr/share/catkin/cmake/test/run_tests.py" "/work/wt/tools/build_ninja/test_results/vrrw_viz/nosetests-test.test_render.py.xml" "--return-code" "\"/usr/bin/cmake\" -E make_directory /work/wt/tools/build_ninja/test_results/vrrw_viz" "/usr/bin/nosetests3 -P --process-timeout=60 /work/wt/tools/catkin_ws/src/vrrw_viz/test/test_render.py --with-xunit --xunit-file=/work/wt/tools/build_ninja/test_results/vrrw_viz/nosetests-test.test_render.py.xml")
set_tests_properties(_ctest_vrrw_viz_nosetests_test.test_render.py PROPERTIES  _BACKTRACE_TRIPLES "/usr/share/catkin/cmake/test/tests.cmake;160;add_test;/usr/share/catkin/cmake/test/nosetests.cmake;83;catkin_run_tests_target;/work/wt/tools/catkin_ws/src/vrrw_viz/CMakeLists.txt;7;catkin_add_nosetests;/work/wt/tools/catkin_ws/src/vrrw_viz/CMakeLists.txt;0;")
