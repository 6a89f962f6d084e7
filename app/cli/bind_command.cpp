// `mocap bind`: binds a take's markers to points of a face mesh and writes the binding JSON that
// `mocap deform` reads.
#include "take_input.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "vertex_range.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/deform/mesh_binding.h"
#include "mocap/io/mesh_io.h"
#include "mocap/deform/retarget.h"
#include "mocap/io/take_io.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

std::vector<std::pair<Eigen::Index, Eigen::Index>> parsePairs(const std::string& text,
                                                              const std::vector<std::string>& labels)
{
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;
  for (const std::string& field : splitList(text, "--pairs")) {
    const std::size_t equals = field.rfind('=');
    const std::string label = field.substr(0, equals == std::string::npos ? 0 : equals);
    const std::string vertex = equals == std::string::npos ? "" : field.substr(equals + 1);
    if (label.empty() || vertex.empty() || vertex.find_first_not_of("0123456789") != std::string::npos ||
        vertex.size() > 9)
      throw UsageError("--pairs needs LABEL=VERTEX entries, not '" + field + "'");
    const auto found = std::find(labels.begin(), labels.end(), label);
    if (found == labels.end())
      throw UsageError("--pairs: " + label + " is not one of the markers being bound");
    pairs.emplace_back(found - labels.begin(), static_cast<Eigen::Index>(std::stol(vertex)));
  }
  return pairs;
}

std::vector<Eigen::Index> vertexRange(const std::string& text, Eigen::Index vertexCount)
{
  const auto [first, last] = parseVertexRange(text, vertexCount);
  std::vector<Eigen::Index> range;
  for (Eigen::Index v = first; v <= last; ++v)
    range.push_back(v);
  return range;
}

struct BindArguments
{
  std::string meshPath, takePath, out;
  std::optional<std::string> pairs, stabilize, markers, vertices;
  std::optional<long long> neutral;
  bool json = false;
};

int runBind(const BindArguments& arguments)
{
  const std::string& meshPath = arguments.meshPath;
  const std::string& takePath = arguments.takePath;
  const std::string& out = arguments.out;
  const std::optional<long long>& neutralNumber = arguments.neutral;

  const Mesh mesh = readMesh(meshPath);
  Take take = readInputTake(takePath);
  const std::vector<std::string> reference =
      arguments.stabilize ? splitList(*arguments.stabilize, "--stabilize") : std::vector<std::string>{};
  (void)stabilizeTake(take, reference);
  std::vector<std::string> labels;
  if (arguments.markers) {
    labels = splitList(*arguments.markers, "--markers");
  } else {
    for (const std::string& label : take.labels())
      if (std::find(reference.begin(), reference.end(), label) == reference.end())
        labels.push_back(label);
  }
  const std::vector<Eigen::Index> markers = markerIndices(take, labels);
  const Eigen::Index neutral = chooseNeutralFrame(take, markers, neutralNumber);
  AutoBindOptions options;
  if (arguments.pairs)
    options.pairs = parsePairs(*arguments.pairs, labels);
  if (arguments.vertices)
    options.vertexSubset = vertexRange(*arguments.vertices, mesh.vertexCount());
  const MeshBinding binding = autoBind(mesh, labels, markerPositions(take, neutral, markers), options);
  const std::string json = bindingJson(binding);
  writeFileAtomically(out, json);

  if (arguments.json) {
    std::cout << json;
    return kExitOk;
  }
  double sum = 0.0, worst = 0.0;
  std::cout << "bound " << binding.markers.size() << " markers of frame " << take.firstFrame() + neutral << " to "
            << meshPath << " (scale " << fixedNumber(binding.alignment.scale, 5) << " mesh units per take unit, "
            << (options.pairs.empty() ? "aligned by ICP" : "aligned on the given pairs") << ")\n";
  for (const MarkerBinding& marker : binding.markers) {
    std::cout << "  " << marker.label << "  "
              << (marker.point.isVertex() ? "vertex " + std::to_string(marker.point.vertices[0])
                                          : "triangle " + std::to_string(marker.point.vertices[0]) + "/" +
                                                std::to_string(marker.point.vertices[1]) + "/" +
                                                std::to_string(marker.point.vertices[2]))
              << "  residual " << fixedNumber(marker.residual, 2) << " mm\n";
    sum += marker.residual;
    worst = std::max(worst, marker.residual);
  }
  std::cout << "residual mean " << fixedNumber(sum / static_cast<double>(binding.markers.size()), 2) << " mm, max "
            << fixedNumber(worst, 2) << " mm\nwrote " << out << '\n';
  return kExitOk;
}

} // namespace

Command addBind(CLI::App& mocap)
{
  CLI::App* command = mocap.add_subcommand("bind", "bind markers to mesh points; per-marker residuals");
  const auto a = std::make_shared<BindArguments>();
  command->add_option("--mesh", a->meshPath, "the face mesh (.obj, .ply, or a glTF rig's neutral: .glb, .gltf)")->required()->type_name("FACE.obj");
  command->add_option("--take", a->takePath, "the take whose neutral frame is bound")->required()->type_name("TAKE");
  command->add_option("--pairs", a->pairs, "at least 3 marker-vertex correspondences (default: ICP)")
      ->type_name("LABEL=VERTEX,...");
  wholeNumberIn(command->add_option("--neutral", a->neutral, "the neutral frame (default: the first complete one)")
                    ->type_name("FRAME"),
                -(1LL << 40), 1LL << 40);
  command->add_option("--stabilize", a->stabilize, "head-mounted markers whose motion is removed first")
      ->type_name("LABELS");
  command->add_option("--markers", a->markers, "the markers bound (default: all but --stabilize)")
      ->type_name("LABELS");
  command->add_option("--vertices", a->vertices, "align to these mesh vertices only")->type_name("FIRST:LAST");
  command->add_option("-o", a->out, "the binding JSON that mocap deform reads")->required()->type_name("BIND.json");
  command->add_flag("--json", a->json, "print the binding JSON");
  return {command, [a] { return runBind(*a); }};
}

} // namespace mocap::cli
