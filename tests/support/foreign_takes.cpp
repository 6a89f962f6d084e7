#include "foreign_takes.h"

#include "mocap/io/c3d_point_types.h"

#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <vector>

namespace mocap::test {

Take distinctValuesTake(int markers, int frames, int channels, int samples)
{
  std::vector<std::string> labels;
  for (int m = 0; m < markers; ++m)
    labels.push_back("P" + std::to_string(m + 1));
  Take take(labels, frames, 100.0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
      const auto mf = static_cast<double>(m * 1000 + f);
      take.setPosition(f, m, Eigen::Vector3d(mf, mf + 0.25, -mf - 0.5));
      take.valid()(f, m) = true;
      take.residuals()(f, m) = 2.0;
    }
  AnalogData& analog = take.analog();
  analog.rate = 100.0 * samples;
  for (int c = 0; c < channels; ++c)
    analog.channels.push_back({"A" + std::to_string(c + 1), "", "V", 1.0, 0.0});
  analog.stored.resize(frames * samples, channels);
  for (Eigen::Index r = 0; r < analog.stored.rows(); ++r)
    for (Eigen::Index c = 0; c < analog.stored.cols(); ++c)
      analog.stored(r, c) = static_cast<double>(c * 10000 + r);
  return take;
}

Take nexusStyleTake(bool typeGroups)
{
  Take take = distinctValuesTake(7, 4);
  const std::vector<std::string> labels = {"LASI",      "LHipAngles", "LHipForce", "LHipMoment",
                                           "LHipPower", "LHipScalar", "RHipAngles"};
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    take.setLabel(m, labels[static_cast<std::size_t>(m)]);
  C3dParameterTree& tree = take.parameters();
  tree.set("POINT", C3dParameter::makeStrings("ANGLES", {"LHipAngles", "RHipAngles", "NotInTheTake"}));
  tree.set("POINT", C3dParameter::makeStrings("FORCES", {"LHipForce"}));
  tree.set("POINT", C3dParameter::makeStrings("MOMENTS", {"LHipMoment"}));
  tree.set("POINT", C3dParameter::makeStrings("POWERS", {"LHipPower"}));
  if (typeGroups) {
    tree.set("POINT", C3dParameter::makeStrings("SCALARS", {"LHipScalar"}));
    tree.set("POINT", C3dParameter::makeStrings("TYPE_GROUPS", {"ANGLES", "ANGLE", "FORCES", "FORCE", "MOMENTS",
                                                                 "MOMENT", "POWERS", "POWER", "SCALARS", "SCALAR"}));
  }
  readC3dPointTypes(tree, take);  // the writer writes the lists from the take's types
  return take;
}

Take nexusCleaningTake(Eigen::Index frames)
{
  const std::vector<std::string> labels = {"LASI",       "RASI",      "LPSI",       "RPSI",     "LHipAngles",
                                           "RHipAngles", "LHipForce", "LHipMoment", "LHipPower"};
  Take take(labels, frames, 100.0);
  const Eigen::Vector3d offsets[] = {{120, 60, 0}, {-120, 60, 0}, {80, -90, 20}, {-80, -90, 20}};
  for (Eigen::Index f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / 100.0;
    const double turn = 0.3 * std::sin(1.3 * t);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d centre(400.0 * t, 30.0 * std::sin(2.0 * t), 950.0 + 10.0 * std::cos(3.0 * t));
    for (Eigen::Index m = 0; m < 4; ++m) {
      const double noise = 0.2 * std::sin(37.0 * static_cast<double>(f) + 11.0 * static_cast<double>(m));
      take.setPosition(f, m, centre + rotation * offsets[m] + Eigen::Vector3d::Constant(noise));
    }
    for (Eigen::Index m = 4; m < take.markerCount(); ++m) {
      const double k = static_cast<double>(m);
      take.setPosition(f, m, Eigen::Vector3d(20.0 * std::sin(2.0 * t + k), 5.0 * std::cos(3.0 * t + k), 10.0 * k * t));
    }
  }
  take.valid().setConstant(true);
  take.residuals().setConstant(1.0);
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    for (Eigen::Index f = 40 + 5 * m; f < 45 + 5 * m; ++f) {
      take.valid()(f, m) = false;
      take.residuals()(f, m) = -1.0;
    }
    take.setPosition(120, m, take.position(120, m) + Eigen::Vector3d(40.0, -40.0, 40.0));
  }
  C3dParameterTree& tree = take.parameters();
  tree.set("POINT", C3dParameter::makeStrings("ANGLES", {"LHipAngles", "RHipAngles"}));
  tree.set("POINT", C3dParameter::makeStrings("FORCES", {"LHipForce"}));
  tree.set("POINT", C3dParameter::makeStrings("MOMENTS", {"LHipMoment"}));
  tree.set("POINT", C3dParameter::makeStrings("POWERS", {"LHipPower"}));
  readC3dPointTypes(tree, take);
  return take;
}

Take plugInGaitTake(const std::string& prefix)
{
  const std::vector<std::string> names = {"LASI", "RASI", "SACR", "PELO", "PELA", "PELL", "PELP",
                                          "CentreOfMass", "CentreOfMassFloor", "LFEO", "LFEA", "LFEL",
                                          "LTIO", "LTIA", "LTIL", "LTIP"};
  std::vector<std::string> labels;
  for (const std::string& name : names)
    labels.push_back(prefix + name);
  constexpr Eigen::Index kFrames = 30;
  Take take(labels, kFrames, 100.0);
  for (Eigen::Index f = 0; f < kFrames; ++f) {
    const double t = static_cast<double>(f) / 100.0;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.8 * t, Eigen::Vector3d(0.2, 0.3, 1.0).normalized()).toRotationMatrix();
    const Eigen::Vector3d pelvis(500.0 * t, 20.0 * std::sin(3.0 * t), 950.0);
    const std::vector<Eigen::Vector3d> offsets = {
        {0, 120, 0},    {0, -120, 0},   {-150, 0, 0},                                         // LASI RASI SACR
        {0, 0, 0},      {100, 0, 0},    {0, 100, 0},    {0, 0, 100},                          // pelvis O A L P
        {0, 0, 50},     {0, 0, -950},                                                         // centre of mass
        {0, 90, -400},  {100, 90, -400}, {0, 190, -400},                                      // femur O A L
        {0, 90, -800},  {100, 90, -800}, {70.7, 160.7, -800}, {0, 90, -700}};                 // tibia O A L P
    for (Eigen::Index m = 0; m < take.markerCount(); ++m)
      take.setPosition(f, m, pelvis + turn * offsets[static_cast<std::size_t>(m)]);
    take.setPosition(f, 8, Eigen::Vector3d(pelvis.x(), pelvis.y(), 0.0));  // the centre of mass on the floor
  }
  take.valid().setConstant(true);
  take.residuals().setConstant(1.0);
  for (Eigen::Index f = 10; f < 13; ++f) {
    take.valid()(f, 4) = false;
    take.residuals()(f, 4) = -1.0;
  }
  return take;
}

std::vector<PointType> pointTypes(const Take& take)
{
  std::vector<PointType> types;
  for (Eigen::Index m = 0; m < take.markerCount(); ++m)
    types.push_back(take.pointType(m));
  return types;
}

} // namespace mocap::test
