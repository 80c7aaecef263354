// The node's parameters read strictly (ParameterTree, readSettings): the shipped parameter files are read whole,
// and a wrong type or a key the node does not have stops it with the parameter's name — roscpp's param() would keep
// the default without a word.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <string>

#include "node_settings.hpp"

namespace bsp = billiard_shot_planner;

namespace
{
/// A YAML node as the parameter server holds it after `rosparam load`: maps as structs, sequences as arrays, and
/// scalars as booleans, integers, doubles (.inf too) or strings, in that order of preference.
XmlRpc::XmlRpcValue toParameters(const YAML::Node& node)
{
  XmlRpc::XmlRpcValue value;
  if (node.IsMap())
  {
    value = XmlRpc::XmlRpcValue();
    for (const auto& member : node)
      value[member.first.as<std::string>()] = toParameters(member.second);
  }
  else if (node.IsSequence())
  {
    value.setSize(static_cast<int>(node.size()));
    for (std::size_t i = 0; i < node.size(); ++i)
      value[static_cast<int>(i)] = toParameters(node[i]);
  }
  else
  {
    bool b;
    int i;
    double d;
    if (YAML::convert<bool>::decode(node, b))
      value = b;
    else if (YAML::convert<int>::decode(node, i))
      value = i;
    else if (YAML::convert<double>::decode(node, d))
      value = d;
    else
      value = node.as<std::string>();
  }
  return value;
}

/// `overlay` loaded over `base`, as a second `rosparam load` merges namespaces.
void mergeInto(XmlRpc::XmlRpcValue& base, XmlRpc::XmlRpcValue overlay)
{
  for (auto& member : overlay)
    if (member.second.getType() == XmlRpc::XmlRpcValue::TypeStruct && base.hasMember(member.first) &&
        base[member.first].getType() == XmlRpc::XmlRpcValue::TypeStruct)
      mergeInto(base[member.first], member.second);
    else
      base[member.first] = member.second;
}

XmlRpc::XmlRpcValue fileParameters(const std::string& name)
{
  return toParameters(YAML::LoadFile(std::string(CONFIG_DIR) + "/" + name));
}

/// readSettings() of `parameters`; the error's field when it fails, "" when it succeeds.
/// What refusedField() answers for parameters the node accepts (an error's field may be empty).
const std::string ACCEPTED = "(accepted)";

/// The field of the error that refuses `parameters`, or ACCEPTED.
std::string refusedField(XmlRpc::XmlRpcValue parameters, std::string* message = nullptr)
{
  bsp::ParameterTree tree(parameters);
  const auto settings = bsp::readSettings(tree);
  if (settings)
    return ACCEPTED;
  if (message)
    *message = settings.error().message;
  return settings.error().field;
}
}  // namespace

TEST(NodeSettings, TheShippedParameterFilesAreReadWhole)
{
  bsp::ParameterTree tree(fileParameters("default.yaml"));
  const auto settings = bsp::readSettings(tree);
  ASSERT_TRUE(settings.ok()) << settings.error().describe();
  EXPECT_EQ(settings.value().shot.cue_contact.friction, 0.7);
  EXPECT_EQ(settings.value().shot.table.pockets.size(), 6u);
  // The file names its pockets as the outline does, the same ids as the table's default pockets.
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(settings.value().shot.table.pockets[i].id, bsp::Table{}.pockets[i].id) << i;
  EXPECT_EQ(settings.value().planning.rollouts, 200);

  XmlRpc::XmlRpcValue overlaid = fileParameters("default.yaml");
  mergeInto(overlaid, fileParameters("paper_masse.yaml"));
  bsp::ParameterTree overlaid_tree(overlaid);
  const auto masse = bsp::readSettings(overlaid_tree);
  ASSERT_TRUE(masse.ok()) << masse.error().describe();
  EXPECT_EQ(masse.value().shot.cue_contact.eta2, 7.0);  // the overlay's
  EXPECT_TRUE(std::isinf(masse.value().shot.cue_end_mass));
}

TEST(NodeSettings, NoParametersAtAllMeanEveryDefault)
{
  EXPECT_EQ(refusedField(XmlRpc::XmlRpcValue()), ACCEPTED);
}

TEST(NodeSettings, AWrongTypeStopsTheNodeNamingTheParameter)
{
  struct Case
  {
    const char* name;
    XmlRpc::XmlRpcValue value;
    const char* expected;
  };
  for (const Case& c : {Case{"ball_radius", XmlRpc::XmlRpcValue("big"), "must be a number, got a string"},
                        Case{"threads", XmlRpc::XmlRpcValue(2.5), "must be an integer, got a number"},
                        Case{"motion/planar", XmlRpc::XmlRpcValue(1), "must be true or false, got an integer"},
                        Case{"target_frame", XmlRpc::XmlRpcValue(3), "must be a string, got an integer"},
                        Case{"planning/rollouts", XmlRpc::XmlRpcValue("many"), "must be an integer, got a string"},
                        Case{"table/cushion/law/type", XmlRpc::XmlRpcValue(true), "must be a string, got a boolean"}})
  {
    XmlRpc::XmlRpcValue parameters = fileParameters("default.yaml");
    XmlRpc::XmlRpcValue* node = &parameters;
    std::string name = c.name;
    for (std::size_t slash; (slash = name.find('/')) != std::string::npos; name = name.substr(slash + 1))
      node = &(*node)[name.substr(0, slash)];
    (*node)[name] = c.value;
    std::string message;
    EXPECT_EQ(refusedField(parameters, &message), c.name);
    EXPECT_EQ(message, c.expected) << c.name;
  }
  // A whole number given where a real is wanted is a number (YAML's `1` for 1.0).
  XmlRpc::XmlRpcValue parameters = fileParameters("default.yaml");
  parameters["motion"]["max_time"] = 30;
  EXPECT_EQ(refusedField(parameters), ACCEPTED);
  // A pocket's id is a name, and one id names one pocket.
  XmlRpc::XmlRpcValue numbered_id = fileParameters("default.yaml");
  numbered_id["table"]["pockets"][2][3] = 7;
  EXPECT_EQ(refusedField(numbered_id), "table/pockets[2][3]");
  XmlRpc::XmlRpcValue twice = fileParameters("default.yaml");
  twice["table"]["pockets"][2][3] = "bottom_left";
  EXPECT_NE(refusedField(twice).find("pockets[2]"), std::string::npos) << refusedField(twice);
}

TEST(NodeSettings, AKeyTheNodeDoesNotHaveStopsItNamingTheKey)
{
  XmlRpc::XmlRpcValue misspelt = fileParameters("default.yaml");
  misspelt["table"]["clth"]["friction"] = 0.2;
  EXPECT_EQ(refusedField(misspelt), "table/clth/friction");

  XmlRpc::XmlRpcValue unknown = fileParameters("default.yaml");
  unknown["cue_speed"] = 2.0;
  std::string message;
  EXPECT_EQ(refusedField(unknown, &message), "cue_speed");
  EXPECT_NE(message.find("is not a parameter of this node"), std::string::npos) << message;

  // A law's own parameter belongs to that law: the constant law has no yield speed, the elastic-plastic one has.
  XmlRpc::XmlRpcValue other_law = fileParameters("default.yaml");
  other_law["table"]["cushion"]["law"]["yield_speed"] = 0.5;
  EXPECT_EQ(refusedField(other_law), "table/cushion/law/yield_speed");
  other_law["table"]["cushion"]["law"]["type"] = "elastic_plastic";
  EXPECT_EQ(refusedField(other_law), ACCEPTED);
}

TEST(NodeSettings, DynamicReconfiguresOwnParametersAreNotTheNodes)
{
  // dynamic_reconfigure keeps the tuned values under ~tuning/: a node restarted without clear_params finds them.
  XmlRpc::XmlRpcValue parameters = fileParameters("default.yaml");
  parameters["tuning"]["cue_contact_restitution"] = 0.6;
  EXPECT_EQ(refusedField(parameters), ACCEPTED);
}

namespace
{
/// `description` as parameters: integer parameters as integers, planar as a boolean, the pockets' list parsed.
XmlRpc::XmlRpcValue asParameters(const bsp::SettingsDescription& description)
{
  XmlRpc::XmlRpcValue parameters;
  auto at = [&parameters](std::string name) -> XmlRpc::XmlRpcValue&
  {
    XmlRpc::XmlRpcValue* node = &parameters;
    for (std::size_t slash; (slash = name.find('/')) != std::string::npos; name = name.substr(slash + 1))
      node = &(*node)[name.substr(0, slash)];
    return (*node)[name];
  };
  const std::set<std::string> integers{"threads", "calibration/max_shots", "planning/rollouts", "planning/threads"};
  for (std::size_t i = 0; i < description.names.size(); ++i)
    if (integers.count(description.names[i]))
      at(description.names[i]) = static_cast<int>(description.values[i]);
    else
      at(description.names[i]) = description.values[i];
  for (std::size_t i = 0; i < description.choice_names.size(); ++i)
  {
    const std::string& name = description.choice_names[i];
    const std::string& value = description.choice_values[i];
    const bool boolean = value == "true" || value == "false";  // no string parameter of the node takes these
    at(name) = name == "table/pockets" ? toParameters(YAML::Load(value))
               : boolean               ? XmlRpc::XmlRpcValue(value == "true")
                                       : XmlRpc::XmlRpcValue(value);
  }
  return parameters;
}
}  // namespace

TEST(NodeSettings, TheDescriptionOfTheSettingsReadsBackToTheSameSettings)
{
  // Settings unlike the defaults wherever a parameter has a choice: the description must carry each of them.
  XmlRpc::XmlRpcValue parameters = fileParameters("default.yaml");
  parameters["target_frame"] = "robot_table";
  parameters["threads"] = 3;
  parameters["motion"]["planar"] = true;
  parameters["motion"]["rolling_model"] = "pooltool";
  parameters["ball_ball"]["friction_model"] = "constant";
  parameters["table"]["cushion"]["law"]["type"] = "elastic_plastic";
  parameters["table"]["cushion"]["law"]["yield_speed"] = 0.7;
  parameters["table"]["pockets"][0][0] = -1.2345678901234567;
  parameters["planning"]["rollouts"] = 321;
  parameters["cockpit"]["animate"] = false;
  parameters["cockpit"]["slow_motion"] = 2.5;
  bsp::ParameterTree tree(parameters);
  const auto settings = bsp::readSettings(tree);
  ASSERT_TRUE(settings.ok()) << settings.error().describe();

  const bsp::SettingsDescription description = bsp::describeSettings(settings.value());
  ASSERT_EQ(description.names.size(), description.values.size());
  ASSERT_EQ(description.choice_names.size(), description.choice_values.size());
  bsp::ParameterTree described(asParameters(description));
  const auto read_back = bsp::readSettings(described);
  ASSERT_TRUE(read_back.ok()) << read_back.error().describe();
  const bsp::SettingsDescription again = bsp::describeSettings(read_back.value());
  EXPECT_EQ(again.names, description.names);
  EXPECT_EQ(again.values, description.values);  // exactly: the numbers go through as doubles
  EXPECT_EQ(again.choice_names, description.choice_names);
  EXPECT_EQ(again.choice_values, description.choice_values);

  // And the description holds what was set.
  auto value_of = [&description](const std::string& name)
  {
    for (std::size_t i = 0; i < description.names.size(); ++i)
      if (description.names[i] == name)
        return description.values[i];
    ADD_FAILURE() << name << " is not described";
    return std::nan("");
  };
  EXPECT_EQ(value_of("table/cushion/law/yield_speed"), 0.7);
  EXPECT_EQ(value_of("planning/rollouts"), 321.0);
  EXPECT_EQ(value_of("table/cloth/friction"), 0.152479);
  EXPECT_EQ(read_back.value().shot.table.pockets[0].centre.x(), -1.2345678901234567);
  EXPECT_EQ(read_back.value().shot.table.pockets[0].id, "bottom_left");
  EXPECT_EQ(read_back.value().target_frame, "robot_table");
}
