#include "billiard_shot_planner/io/calibration_overlay.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>

namespace billiard_shot_planner
{
namespace
{
/// Parameters by the steps of their names ("table" → "cushion" → "restitution"): the nesting of a parameter file.
struct ParameterTree
{
  std::map<std::string, ParameterTree> children;
  double value = 0.0;
};

void emit(YAML::Emitter& out, const ParameterTree& tree)
{
  out << YAML::BeginMap;
  for (const auto& [key, child] : tree.children)
  {
    out << YAML::Key << key << YAML::Value;
    if (child.children.empty())
      out << child.value;
    else
      emit(out, child);
  }
  out << YAML::EndMap;
}
}  // namespace

std::string calibrationOverlayYaml(const FitResult& fit, const std::string& origin)
{
  ParameterTree root;
  for (const FittedParameter& p : fit.parameters)
  {
    if (!p.identifiable)
      continue;
    ParameterTree* node = &root;
    for (std::size_t begin = 0, end = 0; begin <= p.name.size(); begin = end + 1)
    {
      end = std::min(p.name.find('.', begin), p.name.size());
      node = &node->children[p.name.substr(begin, end - begin)];
    }
    node->value = p.value;
  }
  YAML::Emitter out;
  out.SetDoublePrecision(10);
  out << YAML::Comment(origin + " (identifiable parameters only)");
  if (!root.children.empty())
    emit(out, root);
  return std::string(out.c_str()) + "\n";
}

}  // namespace billiard_shot_planner
