#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace yarn_tearing {
namespace ros_layer {

/// Text of a parameter value for error messages, YAML-like, shortened to about 200 characters.
std::string describeValue(const XmlRpc::XmlRpcValue& value);

/// One parameter value with its full name, for typed reads whose errors name both.
///
/// Every read throws ParameterError("invalid parameter <name> = <value>: expected <allowed>")
/// when the value has the wrong type or is out of range.
class ParamValue {
 public:
  /// `name` is the full parameter name used in messages, e.g. "/node/yarns[0].radius".
  ParamValue(std::string name, XmlRpc::XmlRpcValue value);

  const std::string& name() const { return name_; }
  const XmlRpc::XmlRpcValue& raw() const { return value_; }

  /// Throws ParameterError naming this parameter, its value and `allowed`.
  [[noreturn]] void fail(const std::string& allowed) const;

  /// A finite number (integers are accepted) in [min, max]; `unit` is shown in messages, e.g. "m".
  double number(double min, double max, const std::string& unit) const;
  /// A finite number > 0.
  double positiveNumber(const std::string& unit) const;
  /// A finite number >= 0.
  double nonNegativeNumber(const std::string& unit) const;
  /// An integer in [min, max].
  int integer(int min, int max) const;
  bool boolean() const;
  /// A string; `allow_empty` false rejects "".
  std::string string(bool allow_empty) const;
  /// A list of 3 finite numbers.
  Eigen::Vector3d vector3(const std::string& unit) const;
  /// A list of 3 finite numbers whose norm is at most `max_norm` (in `unit`).
  Eigen::Vector3d boundedVector3(double max_norm, const std::string& unit) const;
  /// One of the named choices: the value paired with the string given, e.g.
  /// choice<ProjectionMethod>({{"fast_projection", kFast}, {"gauss_seidel", kGaussSeidel}}).
  template <typename T>
  T choice(const std::vector<std::pair<std::string, T>>& choices) const {
    const std::string given = string(false);
    std::string allowed;
    for (const auto& [name, value] : choices) {
      if (name == given) return value;
      allowed += (allowed.empty() ? "'" : " or '") + name + "'";
    }
    fail(allowed);
  }
  /// A list of integers.
  std::vector<int> integerList() const;

  bool isStruct() const;
  bool isString() const;
  /// True when this value is a map that has `key`.
  bool has(const std::string& key) const;
  /// Member `key` of a map, named "<name>.<key>"; throws ParameterError when missing.
  ParamValue member(const std::string& key) const;
  /// Elements of a list, named "<name>[i]"; throws ParameterError unless a list.
  std::vector<ParamValue> elements() const;
  /// Keys of a map; throws ParameterError unless a map.
  std::vector<std::string> keys() const;
  /// Throws ParameterError unless every key of this map is one of `allowed`.
  void requireKeysIn(const std::vector<std::string>& allowed) const;

 private:
  std::string name_;
  mutable XmlRpc::XmlRpcValue value_;  // XmlRpcValue's accessors are non-const
};

}  // namespace ros_layer
}  // namespace yarn_tearing
