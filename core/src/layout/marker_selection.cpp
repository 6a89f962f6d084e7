#include "mocap/layout/marker_selection.h"

#include "mocap/base/enum_table.h"

namespace mocap {

namespace {

constexpr EnumTable<SelectionMethod, 2> kSelectionMethods{{{
    {SelectionMethod::Pfa, "pfa"},
    {SelectionMethod::Greedy, "greedy"},
}}};

} // namespace

std::string_view selectionMethodName(SelectionMethod method)
{
  return kSelectionMethods.name(method, "greedy");
}

std::string selectionMethodNames()
{
  return kSelectionMethods.names();
}

std::optional<SelectionMethod> parseSelectionMethod(std::string_view name)
{
  return kSelectionMethods.parse(name);
}

} // namespace mocap
