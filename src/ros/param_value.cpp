#include "yarn_tearing/ros/param_value.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "yarn_tearing/ros/parameter_error.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::size_t kMaxDescriptionLength = 200;

void describeInto(XmlRpc::XmlRpcValue& value, std::ostringstream& out) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      out << (static_cast<bool>(value) ? "true" : "false");
      break;
    case XmlRpc::XmlRpcValue::TypeInt:
      out << static_cast<int>(value);
      break;
    case XmlRpc::XmlRpcValue::TypeDouble: {
      // "0.0", not "0": an integral double must not read like the integer it is not.
      std::ostringstream number;
      number << static_cast<double>(value);
      const std::string text = number.str();
      out << text << (text.find_first_of(".eEni") == std::string::npos ? ".0" : "");
      break;
    }
    case XmlRpc::XmlRpcValue::TypeString:
      out << '\'' << static_cast<std::string>(value) << '\'';
      break;
    case XmlRpc::XmlRpcValue::TypeArray:
      out << '[';
      for (int i = 0; i < value.size(); ++i) {
        out << (i > 0 ? ", " : "");
        describeInto(value[i], out);
      }
      out << ']';
      break;
    case XmlRpc::XmlRpcValue::TypeStruct: {
      out << '{';
      bool first = true;
      for (auto& member : value) {
        out << (first ? "" : ", ") << member.first << ": ";
        describeInto(member.second, out);
        first = false;
      }
      out << '}';
      break;
    }
    default:
      out << "(unsupported type)";
  }
}

bool isNumber(const XmlRpc::XmlRpcValue& value) {
  return value.getType() == XmlRpc::XmlRpcValue::TypeInt ||
         value.getType() == XmlRpc::XmlRpcValue::TypeDouble;
}

double toDouble(XmlRpc::XmlRpcValue& value) {
  return value.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(value)
                                                         : static_cast<double>(value);
}

std::string rangeText(double min, double max, const std::string& unit) {
  std::ostringstream text;
  const bool has_min = min > -std::numeric_limits<double>::max();
  const bool has_max = max < std::numeric_limits<double>::max();
  text << "a finite number";
  if (has_min && has_max) {
    text << " in [" << min << ", " << max << "]";
  } else if (has_min) {
    text << " >= " << min;
  } else if (has_max) {
    text << " <= " << max;
  }
  if (!unit.empty()) {
    text << " [" << unit << "]";
  }
  return text.str();
}

/// A hint for strings that look like numbers: YAML 1.1 (rosparam) reads "3.0e8" and "1e-6" as
/// strings; they need a '.' and a signed exponent ("3.0e+8", "1.0e-6").
std::string yamlNumberHint(XmlRpc::XmlRpcValue& value) {
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) {
    return "";
  }
  const std::string text = static_cast<std::string>(value);
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) {
    return "";
  }
  return " (YAML reads '" + text +
         "' as a string: write numbers with a '.' and a signed exponent, e.g. 3.0e+8, 1.0e-6)";
}

}  // namespace

std::string describeValue(const XmlRpc::XmlRpcValue& value) {
  XmlRpc::XmlRpcValue copy = value;
  std::ostringstream out;
  describeInto(copy, out);
  std::string text = out.str();
  if (text.size() > kMaxDescriptionLength) {
    text = text.substr(0, kMaxDescriptionLength) + "...";
  }
  return text;
}

ParamValue::ParamValue(std::string name, XmlRpc::XmlRpcValue value)
    : name_(std::move(name)), value_(std::move(value)) {}

void ParamValue::fail(const std::string& allowed) const {
  throw ParameterError("invalid parameter " + name_ + " = " + describeValue(value_) +
                       ": expected " + allowed + yamlNumberHint(value_));
}

double ParamValue::number(double min, double max, const std::string& unit) const {
  if (!isNumber(value_)) {
    fail(rangeText(min, max, unit));
  }
  const double x = toDouble(value_);
  if (!std::isfinite(x) || x < min || x > max) {
    fail(rangeText(min, max, unit));
  }
  return x;
}

double ParamValue::positiveNumber(const std::string& unit) const {
  if (!isNumber(value_) || !(toDouble(value_) > 0.0) || !std::isfinite(toDouble(value_))) {
    fail("a finite number > 0" + (unit.empty() ? std::string() : " [" + unit + "]"));
  }
  return toDouble(value_);
}

double ParamValue::nonNegativeNumber(const std::string& unit) const {
  return number(0.0, std::numeric_limits<double>::max(), unit);
}

int ParamValue::integer(int min, int max) const {
  const std::string allowed =
      "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (value_.getType() != XmlRpc::XmlRpcValue::TypeInt) {
    fail(allowed);
  }
  const int x = static_cast<int>(value_);
  if (x < min || x > max) {
    fail(allowed);
  }
  return x;
}

bool ParamValue::boolean() const {
  if (value_.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
    fail("true or false");
  }
  return static_cast<bool>(value_);
}

std::string ParamValue::string(bool allow_empty) const {
  if (!isString() || (!allow_empty && static_cast<std::string>(value_).empty())) {
    fail(allow_empty ? "a string" : "a non-empty string");
  }
  return static_cast<std::string>(value_);
}

Eigen::Vector3d ParamValue::vector3(const std::string& unit) const {
  const std::string allowed =
      "a list of 3 finite numbers [x, y, z]" + (unit.empty() ? std::string() : " [" + unit + "]");
  if (value_.getType() != XmlRpc::XmlRpcValue::TypeArray || value_.size() != 3) {
    fail(allowed);
  }
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!isNumber(value_[i]) || !std::isfinite(toDouble(value_[i]))) {
      fail(allowed);
    }
    v[i] = toDouble(value_[i]);
  }
  return v;
}

Eigen::Vector3d ParamValue::boundedVector3(double max_norm, const std::string& unit) const {
  const Eigen::Vector3d v = vector3(unit);
  if (!(v.norm() <= max_norm)) {
    std::ostringstream allowed;
    allowed << "a list of 3 finite numbers [x, y, z] of magnitude <= " << max_norm
            << (unit.empty() ? std::string() : " [" + unit + "]");
    fail(allowed.str());
  }
  return v;
}

std::vector<int> ParamValue::integerList() const {
  if (value_.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    fail("a list of integers");
  }
  std::vector<int> list;
  for (int i = 0; i < value_.size(); ++i) {
    if (value_[i].getType() != XmlRpc::XmlRpcValue::TypeInt) {
      fail("a list of integers");
    }
    list.push_back(static_cast<int>(value_[i]));
  }
  return list;
}

bool ParamValue::isStruct() const { return value_.getType() == XmlRpc::XmlRpcValue::TypeStruct; }

bool ParamValue::isString() const { return value_.getType() == XmlRpc::XmlRpcValue::TypeString; }

bool ParamValue::has(const std::string& key) const { return isStruct() && value_.hasMember(key); }

ParamValue ParamValue::member(const std::string& key) const {
  if (!has(key)) {
    fail("a map with the key '" + key + "'");
  }
  return ParamValue(name_ + "." + key, value_[key]);
}

std::vector<ParamValue> ParamValue::elements() const {
  if (value_.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    fail("a list");
  }
  std::vector<ParamValue> list;
  for (int i = 0; i < value_.size(); ++i) {
    list.emplace_back(name_ + "[" + std::to_string(i) + "]", value_[i]);
  }
  return list;
}

std::vector<std::string> ParamValue::keys() const {
  if (!isStruct()) {
    fail("a map");
  }
  std::vector<std::string> list;
  for (const auto& member : value_) {
    list.push_back(member.first);
  }
  return list;
}

void ParamValue::requireKeysIn(const std::vector<std::string>& allowed) const {
  for (const std::string& key : keys()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (const std::string& a : allowed) {
        list += (list.empty() ? "" : ", ") + a;
      }
      throw ParameterError("invalid parameter " + name_ + "." + key + ": unknown key '" + key +
                           "'; allowed keys: " + list);
    }
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
