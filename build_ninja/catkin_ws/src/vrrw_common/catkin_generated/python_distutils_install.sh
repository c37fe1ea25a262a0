#!/bin/sh

if [ -n "$DESTDIR" ] ; then
    case $DESTDIR in
        /*) # ok
            ;;
        *)
            /bin/echo "DESTDIR argument must be absolute... "
            /bin/echo "otherwise python's distutils will bork things."
            exit 1
    esac
fi

echo_and_run() { echo "+ $@" ; "$@" ; }

echo_and_run cd "/work/wt/tools/catkin_ws/src/vrrw_common"

# ensure that Python install destination exists
echo_and_run mkdir -p "$DESTDIR/usr/local/lib/python3/dist-packages"

# Note that PYTHONPATH is pulled from the environment to support installing
# into one location when some dependencies were installed in another
# location, #123.
echo_and_run /usr/bin/env \
    PYTHONPATH="/usr/local/lib/python3/dist-packages:/work/wt/tools/build_ninja/lib/python3/dist-packages:$PYTHONPATH" \
    CATKIN_BINARY_DIR="/work/wt/tools/build_ninja" \
    "/usr/bin/python3" \
    "/work/wt/tools/catkin_ws/src/vrrw_common/setup.py" \
    egg_info --egg-base /work/wt/tools/build_ninja/catkin_ws/src/vrrw_common \
    build --build-base "/work/wt/tools/build_ninja/catkin_ws/src/vrrw_common" \
    install \
    --root="${DESTDIR-/}" \
    --install-layout=deb --prefix="/usr/local" --install-scripts="/usr/local/bin"
