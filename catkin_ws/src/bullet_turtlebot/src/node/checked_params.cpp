#include "checked_params.hpp"

#include <xmlrpcpp/XmlRpcValue.h>

#include <cmath>
#include <sstream>

namespace bullet_turtlebot {
namespace {

std::string shown(XmlRpc::XmlRpcValue& value) {
  std::ostringstream out;
  value.write(out);
  return out.str();
}

[[noreturn]] void refuse(const ros::NodeHandle& pnh, const std::string& name, const std::string& got,
                         const std::string& rule) {
  throw ParameterError(pnh.resolveName(name) + " is " + got + ": it must be " + rule + " (set it with " +
                       name + ":=VALUE in the launch file, or _" + name + ":=VALUE with rosrun)");
}

}  // namespace

double checked_number(const ros::NodeHandle& pnh, const std::string& name, double fallback, double lo,
                      double hi, const std::string& rule) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return fallback;
  double number = 0.0;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    number = static_cast<double>(value);
  } else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    number = static_cast<int>(value);
  } else {
    refuse(pnh, name, "'" + shown(value) + "', not a number", rule);
  }
  if (!std::isfinite(number) || number < lo || number > hi) refuse(pnh, name, shown(value), rule);
  return number;
}

int checked_int(const ros::NodeHandle& pnh, const std::string& name, int fallback, int lo, int hi,
                const std::string& rule) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return fallback;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeInt) {
    refuse(pnh, name, "'" + shown(value) + "', not a whole number", rule);
  }
  const int number = static_cast<int>(value);
  if (number < lo || number > hi) refuse(pnh, name, shown(value), rule);
  return number;
}

std::string checked_string(const ros::NodeHandle& pnh, const std::string& name, const std::string& fallback,
                           const std::string& rule) {
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam(name, value)) return fallback;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) {
    refuse(pnh, name, "'" + shown(value) + "', not a name", rule);
  }
  const std::string text = static_cast<std::string>(value);
  if (text.empty()) refuse(pnh, name, "empty", rule);
  return text;
}

}  // namespace bullet_turtlebot
