#include "review_arguments.h"

#include "arguments.h"
#include "cli_error.h"

#include <cstdio>

namespace mocap::cli {

void defineReviewOptions(CLI::App& command, ReviewArguments& a)
{
  command.add_option("TAKE", a.take, "the take (.c3d or .trc)")->required()->type_name("TAKE");
  command.add_option("-o,--output", a.output,
                     "the review video: .mp4 (H.264, else MPEG-4; MJPEG .avi beside it when neither encoder "
                     "exists) or .avi (MJPEG)")
      ->required()
      ->type_name("OUT.mp4|OUT.avi");
  command.add_option("--frames", a.frames, "the frames rendered, FIRST:LAST as the take numbers them (default: all)")
      ->type_name("FIRST:LAST");
  command.add_option("--size", a.size, "the video's width x height in pixels, even (default 1280x720)")->type_name("WxH");
  command.add_option("--video", a.video, "a reference video drawn beside the 3D view")->type_name("REF.mp4");
  numberIn(command.add_option("--offset", a.offset,
                              "seconds of reference video before the take's first frame (video time = "
                              "frame / take rate + offset; default 0)")
               ->type_name("S"),
           -86400.0, 86400.0);
  command.add_option("--mesh", a.mesh, "a face mesh (.obj, .ply, .glb) driven by the markers, drawn over them")
      ->type_name("FACE.obj");
  command.add_option("--binding", a.binding, "the markers' binding to the mesh or rig (mocap bind's JSON)")
      ->type_name("BIND.json");
  command.add_option("--solve", a.solve,
                     "a blendshape rig (.glb/.gltf, or an ICT FaceKit neutral .obj with --rig-shapes): solve the take "
                     "to its weights and draw it posed beside the markers")
      ->type_name("RIG.glb");
  command.add_option("--rig-shapes", a.rigShapes, "the folder of the rig's shape OBJs (for an .obj rig)")->type_name("DIR");
  command.add_option("--select", a.select, "markers drawn selected: labelled, with trails (comma-separated labels)")
      ->type_name("LABELS");
  wholeNumberIn(command.add_option("--trails", a.trails, "frames of trail before and after the current one (default 50)")
                    ->type_name("N"),
                0, 1000);
  command.add_flag("--json", a.json, "print what was written as JSON on stdout");
}

std::pair<int, int> parseReviewSize(const std::string& text)
{
  int width = 0, height = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || (x != 'x' && x != 'X'))
    throw UsageError("--size needs WIDTHxHEIGHT, e.g. 1280x720, not '" + text + "'");
  if (width < 64 || height < 64 || width > 7680 || height > 7680)
    throw UsageError("--size " + text + ": each side must be in [64, 7680]");
  if (width % 2 != 0 || height % 2 != 0)
    throw UsageError("--size " + text + ": video encoders need even sides");
  return {width, height};
}

} // namespace mocap::cli
