// `mocap rig`: converts a blendshape rig (an OBJ folder or a glTF file) to one GLB, optionally
// with only some shapes, a contiguous range of vertices, or without motion below a tolerance.
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "rig_input.h"
#include "vertex_range.h"

#include "mocap/base/file_io.h"
#include "mocap/base/json_writer.h"
#include "mocap/base/stopwatch.h"
#include "mocap/io/gltf_writer.h"

#include <iostream>
#include <memory>
#include <optional>

namespace mocap::cli {

namespace {

struct RigArguments
{
  std::string meshPath, shapesPath, out;
  std::optional<std::string> only, vertices;
  double tolerance = 0.0;
  bool json = false;
};

Eigen::Index movedVertices(const BlendshapeRig& rig)
{
  Eigen::Index total = 0;
  for (const SparseShape& shape : rig.shapes)
    total += shape.size();
  return total;
}

void printRigJson(const RigArguments& arguments, const BlendshapeRig& rig, std::size_t bytes,
                  double readSeconds)
{
  JsonWriter json;
  json.beginObject();
  json.key("vertices").value(static_cast<std::int64_t>(rig.neutral.vertexCount()));
  json.key("triangles").value(static_cast<std::int64_t>(rig.neutral.triangles().size()));
  json.key("shapes").beginArray();
  for (const SparseShape& shape : rig.shapes)
    json.value(shape.name);
  json.endArray();
  json.key("moved_vertices").value(static_cast<std::int64_t>(movedVertices(rig)));
  json.key("read_seconds").value(readSeconds);
  json.key("bytes").value(static_cast<std::int64_t>(bytes));
  json.key("output").value(arguments.out);
  json.endObject();
  std::cout << json.str() << '\n';
}

int runRig(const RigArguments& arguments)
{
  if (lowerExtension(arguments.out) != "glb")
    throw UsageError("-o must be a .glb file, not '" + arguments.out + "'");
  const Stopwatch read;
  BlendshapeRig rig = readInputRig(arguments.meshPath, arguments.shapesPath, arguments.only);
  const double readSeconds = read.seconds();
  if (arguments.vertices) {
    const auto [first, last] = parseVertexRange(*arguments.vertices, rig.neutral.vertexCount());
    rig = rigRegion(rig, first, last);
  }
  if (arguments.tolerance > 0.0)
    rig = prunedRig(rig, arguments.tolerance);
  // No animation, so the frame rate is not written.
  const std::string glb = rigGlb(rig, Eigen::MatrixXd(), 1.0);
  writeFileAtomically(arguments.out, glb);
  if (arguments.json) {
    printRigJson(arguments, rig, glb.size(), readSeconds);
    return kExitOk;
  }
  std::cout << "wrote " << arguments.out << ": " << rig.neutral.vertexCount() << " vertices, "
            << rig.neutral.triangles().size() << " triangles, " << rig.shapeCount() << " shapes ("
            << movedVertices(rig) << " moved vertices), " << glb.size() << " bytes\n";
  return kExitOk;
}

} // namespace

Command addRig(CLI::App& mocap)
{
  CLI::App* command =
      mocap.add_subcommand("rig", "convert a blendshape rig (OBJ folder or glTF) to one GLB, optionally cut to a vertex range");
  const auto a = std::make_shared<RigArguments>();
  command->add_option("--mesh", a->meshPath, "the rig: its neutral (.obj, .ply) with --shapes, or a glTF rig (.glb, .gltf)")
      ->required()
      ->type_name("NEUTRAL.obj|RIG.glb");
  command->add_option("--shapes", a->shapesPath, "folder with one OBJ per shape, named after it")->type_name("DIR");
  command->add_option("--only", a->only, "keep only these shapes, in this order")->type_name("NAME,...");
  command->add_option("--vertices", a->vertices, "keep only these vertices (renumbered from 0) and the faces among them")
      ->type_name("FIRST:LAST");
  numberIn(command->add_option("--tolerance", a->tolerance,
                               "drop shape entries that move no axis more than D mesh units (1e-4 on ICT's cm: 1 µm)")
               ->type_name("D"),
           0.0, 1e6)
      ->capture_default_str();
  command->add_option("-o", a->out, "the rig as GLB: neutral and one morph target per shape")->required()->type_name("RIG.glb");
  command->add_flag("--json", a->json, "print JSON: vertices, triangles, shape names, moved vertices, bytes");
  return {command, [a] { return runRig(*a); }};
}

} // namespace mocap::cli
