# Only the targets that include vrrw_common's headers get its include directories and libraries, so the compile
# flags (and ccache's hits) of the package's other targets stay as they are.
#   vrrw_common_use(TARGET...)       options, joint mapping and the roscpp helpers (vrrw_common_ros)
#   vrrw_common_use_core(TARGET...)  options and joint mapping only, for ROS-free targets
function(vrrw_common_use)
  foreach(target ${ARGN})
    target_include_directories(${target} SYSTEM PRIVATE ${vrrw_common_INCLUDE_DIRS})
    target_link_libraries(${target} ${vrrw_common_LIBRARIES})
  endforeach()
endfunction()

function(vrrw_common_use_core)
  # catkin lists the package's own include directory and its libraries (vrrw_common, vrrw_common_ros) first
  list(GET vrrw_common_INCLUDE_DIRS 0 include)
  list(GET vrrw_common_LIBRARIES 0 library)
  foreach(target ${ARGN})
    target_include_directories(${target} SYSTEM PRIVATE ${include})
    target_link_libraries(${target} ${library})
  endforeach()
endfunction()
