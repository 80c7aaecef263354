#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <set>
#include <string>
#include <vector>

#include "billiard_shot_planner/core/expected.hpp"

namespace billiard_shot_planner
{
/// The node's private parameters as one tree, read by name ("table/cloth/friction"). A value of the wrong type is
/// refused naming the parameter (roscpp's param() would keep the default without a word), and every name a reader
/// asks for is remembered, so that what nobody asked for — a misspelt or unknown key — can be named too.
class ParameterTree
{
public:
  /// `parameters`: the private namespace as the parameter server returns it (a struct; anything else is empty).
  explicit ParameterTree(const XmlRpc::XmlRpcValue& parameters);

  /// Each leaves `value` as it is when the parameter is absent. A double takes an integer too; an int, a bool and
  /// a string take only their own type.
  Status read(const std::string& name, double& value);
  Status read(const std::string& name, int& value);
  Status read(const std::string& name, bool& value);
  Status read(const std::string& name, std::string& value);
  /// A parameter of any type (a list such as table/pockets), or nullptr when absent.
  const XmlRpc::XmlRpcValue* find(const std::string& name);
  /// Whether the parameter is set (it counts as read).
  bool has(const std::string& name) { return find(name) != nullptr; }

  /// The first parameter no reader asked for, outside the subtrees `ignored` ("tuning": dynamic_reconfigure's own),
  /// as an error that names it.
  Status checkEveryParameterWasRead(const std::vector<std::string>& ignored) const;

private:
  /// The one reading behind read(): find, check the type, convert.
  template <class T>
  Status readAs(const std::string& name, T& value);
  Status checkRead(const XmlRpc::XmlRpcValue& subtree, const std::string& path,
                   const std::vector<std::string>& ignored) const;

  XmlRpc::XmlRpcValue root_;
  std::set<std::string> read_;
};

}  // namespace billiard_shot_planner
