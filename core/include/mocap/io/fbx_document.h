#pragma once

#include "mocap/base/length_unit.h"
#include "mocap/io/fbx_binary.h"

#include <Eigen/Core>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocap {

/// The axis that points up in the coordinates an FBX file holds. The file declares it (with a
/// right-handed front and side axis: Y-up faces +Z, Z-up faces −Y) and the coordinates are written
/// as they are, so readers turn the scene into their own frame.
enum class FbxUpAxis
{
  Y,
  Z,
};

/// "y" or "z"; parseFbxUpAxis reads them back (case-insensitive), nullopt for anything else.
[[nodiscard]] std::string_view fbxUpAxisName(FbxUpAxis axis);
[[nodiscard]] std::optional<FbxUpAxis> parseFbxUpAxis(std::string_view text);

/// What GlobalSettings declares and the animation spans: frames 0…frameCount−1 at startSeconds +
/// i / frameRate (the take's first frame is time 0; a recording keeps its timecode's start).
struct FbxSceneSettings
{
  FbxUpAxis up = FbxUpAxis::Y;
  LengthUnit unit = LengthUnit::Centimetre;
  double frameRate = 0.0;
  Eigen::Index frameCount = 0;
  double startSeconds = 0.0;
};

/// How an animation curve moves between keys.
enum class FbxInterpolation
{
  Linear,
  Constant,
};

/// An FBX 7.4 scene under construction: the file's fixed parts (header extension, file id,
/// GlobalSettings, Documents, Definitions with a count per object kind, Takes), the Objects and
/// their Connections, and one animation stack with one layer. Object ids are 1, 2, 3… (0 is the
/// scene's root). Each method is O(its data).
class FbxDocument
{
public:
  /// Throws InvalidArgument for a rate that is not positive and finite or a negative frame count.
  explicit FbxDocument(const FbxSceneSettings& settings);

  struct Object
  {
    std::int64_t id = 0;
    FbxNode* node = nullptr;  ///< valid while the document lives
  };

  /// A new object: node `kind` ("Model", "Geometry", "Deformer", …) with its id, "name\0\1class"
  /// and `subtype` ("Null", "Mesh", "BlendShapeChannel", … or ""), counted in Definitions.
  Object addObject(std::string_view kind, std::string_view name, std::string_view className, std::string_view subtype);
  /// "OO": `child` belongs to `parent` (0 = the scene's root).
  void connect(std::int64_t child, std::int64_t parent);
  /// "OP": `child` drives property `property` of `parent`.
  void connectProperty(std::int64_t child, std::int64_t parent, std::string_view property);

  /// Animates property `property` of object `target`: an AnimationCurveNode called `nodeName`
  /// with one AnimationCurve per channel ("d|X"…), `values[c]` holding one value per frame. Each
  /// frame is a key, or when `keyFrames` is given only the frames `keyFrames[c]` lists (ascending,
  /// e.g. reduceKeys' choice for that channel). Throws InvalidArgument when a channel's value
  /// count is not frameCount, or for key frames out of order, out of range or of another count.
  void animate(std::int64_t target, std::string_view property, std::string_view nodeName,
               const std::vector<std::string>& channels, const std::vector<std::vector<float>>& values,
               FbxInterpolation interpolation, const std::vector<std::vector<Eigen::Index>>* keyFrames = nullptr);

  /// The finished file. O(file size).
  [[nodiscard]] std::string bytes() const;

  [[nodiscard]] const FbxSceneSettings& settings() const { return m_settings; }

private:
  FbxSceneSettings m_settings;
  std::vector<std::int64_t> m_keyTimes;
  std::int64_t m_startTicks = 0;  // the first key's time
  FbxNode m_objects{"Objects"};
  FbxNode m_connections{"Connections"};
  std::map<std::string, int, std::less<>> m_counts;
  std::int64_t m_nextId = 1;
  std::int64_t m_layer = 0;
};

/// Appends a Properties70 record `P: name, type, label, flags` to `properties`; add the values to
/// the returned node. O(1).
FbxNode& addFbxProperty(FbxNode& properties, std::string_view name, std::string_view type, std::string_view label,
                        std::string_view flags);

} // namespace mocap
