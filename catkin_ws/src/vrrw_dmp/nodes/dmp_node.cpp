// dmp_node: learn a DMP from a bag, a CSV or a JointTrajectory (~learn) and plan with it (~plan).
// Parameters: ~basis_count ~alpha ~K ~D ~scaling (learning defaults), ~dt (plan sample period),
// ~model (a model YAML to load at start).
#include <ros/ros.h>

#include "../src/ros/dmp_services.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "dmp_node");
  ros::NodeHandle private_node("~");
  try
  {
    vrrw_dmp::DmpServices services(private_node);
    ros::spin();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM("dmp_node: " << e.what());
    return 1;
  }
  return 0;
}
