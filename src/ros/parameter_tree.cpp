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

namespace
{
using Type = XmlRpc::XmlRpcValue::Type;

/// What a parameter read into a T accepts (its types on the parameter server), how an error names it, and the
/// conversion: a double takes an integer too; an int, a bool and a string only their own type.
template <class T>
struct Reading;
template <>
struct Reading<double>
{
  static constexpr const char* WANTED = "a number";
  static bool accepts(Type t) { return t == XmlRpc::XmlRpcValue::TypeDouble || t == XmlRpc::XmlRpcValue::TypeInt; }
  static double convert(XmlRpc::XmlRpcValue& v)
  {
    return v.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(v) : static_cast<double>(v);
  }
};
template <>
struct Reading<int>
{
  static constexpr const char* WANTED = "an integer";
  static bool accepts(Type t) { return t == XmlRpc::XmlRpcValue::TypeInt; }
  static int convert(XmlRpc::XmlRpcValue& v) { return static_cast<int>(v); }
};
template <>
struct Reading<bool>
{
  static constexpr const char* WANTED = "true or false";
  static bool accepts(Type t) { return t == XmlRpc::XmlRpcValue::TypeBoolean; }
  static bool convert(XmlRpc::XmlRpcValue& v) { return static_cast<bool>(v); }
};
template <>
struct Reading<std::string>
{
  static constexpr const char* WANTED = "a string";
  static bool accepts(Type t) { return t == XmlRpc::XmlRpcValue::TypeString; }
  static std::string convert(XmlRpc::XmlRpcValue& v) { return static_cast<std::string>(v); }
};
}  // namespace

template <class T>
Status ParameterTree::readAs(const std::string& name, T& value)
{
  const XmlRpc::XmlRpcValue* found = find(name);
  if (!found)
    return {};
  XmlRpc::XmlRpcValue copy = *found;  // XmlRpcValue's conversions are not const
  if (!Reading<T>::accepts(copy.getType()))
    return wrongType(name, Reading<T>::WANTED, copy);
  value = Reading<T>::convert(copy);
  return {};
}

Status ParameterTree::read(const std::string& name, double& value)
{
  return readAs(name, value);
}

Status ParameterTree::read(const std::string& name, int& value)
{
  return readAs(name, value);
}

Status ParameterTree::read(const std::string& name, bool& value)
{
  return readAs(name, value);
}

Status ParameterTree::read(const std::string& name, std::string& value)
{
  return readAs(name, value);
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
