#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <initializer_list>

namespace yarn_tearing {
namespace ros_layer {
namespace testing {

/// An XmlRpc list of numbers (or of other lists), as rosparam would load it.
inline XmlRpc::XmlRpcValue list(std::initializer_list<XmlRpc::XmlRpcValue> items) {
  XmlRpc::XmlRpcValue value;
  value.setSize(static_cast<int>(items.size()));
  int i = 0;
  for (const XmlRpc::XmlRpcValue& item : items) {
    value[i++] = item;
  }
  return value;
}

/// [[0, 0], [0.01, 1e8 Pa], [0.05, 3e8 Pa]]: yield at 1 %, break at 5 % and 300 MPa.
inline XmlRpc::XmlRpcValue curve() {
  return list({list({0.0, 0.0}), list({0.01, 1.0e8}), list({0.05, 3.0e8})});
}

inline XmlRpc::XmlRpcValue inlineMaterial() {
  XmlRpc::XmlRpcValue material;
  material["density"] = 1500.0;
  material["stress_strain"] = curve();
  return material;
}

/// A valid yarn entry of ~yarns named `name`.
inline XmlRpc::XmlRpcValue validYarn(const std::string& name = "a") {
  XmlRpc::XmlRpcValue yarn;
  yarn["name"] = name;
  yarn["material"] = inlineMaterial();
  yarn["radius"] = 1.0e-4;
  yarn["length"] = 0.1;
  yarn["num_vertices"] = 5;
  yarn["start"] = list({0.0, 0.0, 0.0});
  yarn["direction"] = list({0.0, 0.0, -1.0});
  yarn["pinned"] = list({0});
  return yarn;
}

}  // namespace testing
}  // namespace ros_layer
}  // namespace yarn_tearing
