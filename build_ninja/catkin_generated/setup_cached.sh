#!/usr/bin/env sh
# generated from catkin/python/catkin/environment_cache.py

# based on a snapshot of the environment before and after calling the setup script
# it emulates the modifications of the setup script without recurring computations

# new environment variables
export CMAKE_PREFIX_PATH='/work/wt/tools/build_ninja/devel'
export LD_LIBRARY_PATH='/work/wt/tools/build_ninja/devel/lib'
export PKG_CONFIG_PATH=''
export PYTHONPATH='/work/wt/tools/build_ninja/devel/lib/python3/dist-packages'
export ROSLISP_PACKAGE_DIRECTORIES='/work/wt/tools/build_ninja/devel/share/common-lisp'
export ROS_DISTRO='Debian'
export ROS_ETC_DIR='//etc/ros'
export ROS_PACKAGE_PATH='/work/wt/tools'
export ROS_PYTHON_VERSION='3'
export ROS_VERSION='1'

# modified environment variables