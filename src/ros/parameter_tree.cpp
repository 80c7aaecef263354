#include "parameter_tree.hpp"

#include <algorithm>
#include <sstream>

namespace billiard_shot_planner
{
namespace
{
const char* typeName(XmlRpc::XmlRpcValue::Type type)
{
  switch (type)
  {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return "a boolean";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an integer";
    case XmlRpc::XmlRpcValue::TypeDouble:
      return "a number";
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a namespace of parameters";
    default:
      return "a value of another type";
  }
}

Error wrongType(const std::string& name, const char* wanted, const XmlRpc::XmlRpcValue& value)
{
  return invalidArgument(name, std::string("must be ") + wanted + ", got " + typeName(value.getType()));
}

/// "table/cloth/friction" → {"table", "cloth", "friction"}.
std::vector<std::string> splitName(const std::string& name)
{
  std::vector<std::string> parts;
  std::stringstream stream(name);
  for (std::string part; std::getline(stream, part, '/');)
    parts.push_back(part);
  return parts;
}
}  // namespace

ParameterTree::ParameterTree(const XmlRpc::XmlRpcValue& parameters) : root_(parameters)
{
  if (root_.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    root_ = XmlRpc::XmlRpcValue();
}

const XmlRpc::XmlRpcValue* ParameterTree::find(const std::string& name)
{
  read_.insert(name);
  XmlRpc::XmlRpcValue* node = &root_;
  for (const std::string& part : splitName(name))
  {
    if (node->getType() != XmlRpc::XmlRpcValue::TypeStruct || !node->hasMember(part))
      return nullptr;
    node = &(*node)[part];
  }
  return node;
}

Status ParameterTree::read(const std::string& name, double& value)
{
  const XmlRpc::XmlRpcValue* found = find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue copy = *found;  // XmlRpcValue's conversions are not const
  if (copy.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    value = static_cast<double>(copy);
  else if (copy.getType() == XmlRpc::XmlRpcValue::TypeInt)
    value = static_cast<int>(copy);
  else
    return wrongType(name, "a number", copy);
  return {};
}

Status ParameterTree::read(const std::string& name, int& value)
{
  const XmlRpc::XmlRpcValue* found = find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue copy = *found;
  if (copy.getType() != XmlRpc::XmlRpcValue::TypeInt)
    return wrongType(name, "an integer", copy);
  value = static_cast<int>(copy);
  return {};
}

Status ParameterTree::read(const std::string& name, bool& value)
{
  const XmlRpc::XmlRpcValue* found = find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue copy = *found;
  if (copy.getType() != XmlRpc::XmlRpcValue::TypeBoolean)
    return wrongType(name, "true or false", copy);
  value = static_cast<bool>(copy);
  return {};
}

Status ParameterTree::read(const std::string& name, std::string& value)
{
  const XmlRpc::XmlRpcValue* found = find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue copy = *found;
  if (copy.getType() != XmlRpc::XmlRpcValue::TypeString)
    return wrongType(name, "a string", copy);
  value = static_cast<std::string>(copy);
  return {};
}

Status ParameterTree::checkEveryParameterWasRead(const std::vector<std::string>& ignored) const
{
  return checkRead(root_, "", ignored);
}

Status ParameterTree::checkRead(const XmlRpc::XmlRpcValue& subtree, const std::string& path,
                                const std::vector<std::string>& ignored) const
{
  if (!path.empty() && (read_.count(path) || std::count(ignored.begin(), ignored.end(), path)))
    return {};
  if (subtree.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    return path.empty()
               ? Status{}  // no parameters at all
               : invalidArgument(path, "is not a parameter of this node (misspelt, or of another law or version?)");
  for (auto member = subtree.begin(); member != subtree.end(); ++member)
    if (Status status = checkRead(member->second, path.empty() ? member->first : path + "/" + member->first, ignored);
        !status)
      return status;
  return {};
}

}  // namespace billiard_shot_planner
