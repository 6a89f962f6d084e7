#include "mocap/base/enum_table.h"
#include "mocap/base/length_unit.h"
#include "mocap/cleaning/fill/gap_fill.h"
#include "mocap/cleaning/smoothing.h"
#include "mocap/cleaning/smoothing_spline.h"
#include "mocap/cleaning/spike_detection.h"
#include "mocap/deform/face_rig.h"
#include "mocap/deform/laplacian_weights.h"
#include "mocap/deform/rbf_deformer.h"
#include "mocap/deform/retarget.h"
#include "mocap/io/take_io.h"
#include "mocap/layout/marker_selection.h"
#include "mocap/model/provenance.h"

#include <gtest/gtest.h>

namespace mocap {
namespace {

enum class Colour
{
  Red,
  Green,
  Blue,
};

constexpr EnumTable<Colour, 4> kColours{{{
    {Colour::Red, "red"},
    {Colour::Green, "green"},
    {Colour::Blue, "blue"},
    {Colour::Red, "rouge"},  // an alias: parsed, never written
}}};

TEST(EnumTable, NamesParsesAndListsItsEntries)
{
  static_assert(kColours.name(Colour::Green, "?") == "green");
  static_assert(*kColours.parse("blue") == Colour::Blue);
  EXPECT_EQ(kColours.name(Colour::Red, "?"), "red");
  EXPECT_EQ(kColours.name(static_cast<Colour>(7), "?"), "?");
  EXPECT_EQ(kColours.parse("rouge"), Colour::Red);
  EXPECT_EQ(kColours.parse("Red"), std::nullopt);
  EXPECT_EQ(kColours.parse(""), std::nullopt);
  EXPECT_EQ(kColours.names(), "red|green|blue");
  EXPECT_EQ(kColours.names(", "), "red, green, blue");
}

// Every enum's name and parse go through a table: each name parses back to its value.
template <typename Enum, typename Name, typename Parse>
void expectRoundTrip(std::initializer_list<Enum> values, Name name, Parse parse)
{
  for (const Enum value : values) {
    const std::string_view text = name(value);
    EXPECT_FALSE(text.empty());
    EXPECT_EQ(parse(text), value) << text;
  }
  EXPECT_EQ(parse("no such name"), std::nullopt);
}

TEST(EnumTable, EveryNamedEnumRoundTrips)
{
  expectRoundTrip({SelectionMethod::Pfa, SelectionMethod::Greedy}, selectionMethodName, parseSelectionMethod);
  expectRoundTrip({LengthUnit::Millimetre, LengthUnit::Centimetre, LengthUnit::Metre}, unitName, parseLengthUnit);
  expectRoundTrip({SampleOrigin::Measured, SampleOrigin::Filled, SampleOrigin::Edited}, sampleOriginName,
                  parseSampleOrigin);
  expectRoundTrip({SampleOperation::Smoothed, SampleOperation::Stabilized}, sampleOperationName, parseSampleOperation);
  expectRoundTrip({SmoothingSplineMode::Gcv, SmoothingSplineMode::ErrorVariance, SmoothingSplineMode::Cutoff},
                  smoothingSplineModeName, parseSmoothingSplineMode);
  expectRoundTrip({SpikeMethod::Paper, SpikeMethod::Robust}, spikeMethodName, parseSpikeMethod);
  for (const FillMethod method : allFillMethods())
    EXPECT_EQ(parseFillMethod(fillMethodName(method)), method);
  expectRoundTrip({SmoothMethod::BSpline, SmoothMethod::Butterworth, SmoothMethod::Gcvspl, SmoothMethod::SavGol},
                  smoothMethodName, parseSmoothMethod);
  expectRoundTrip({LaplacianWeights::Uniform, LaplacianWeights::Cotangent, LaplacianWeights::MeanValue},
                  laplacianWeightsName, parseLaplacianWeights);
  expectRoundTrip({RetargetScale::Uniform, RetargetScale::PerAxis}, retargetScaleName, parseRetargetScale);
  expectRoundTrip({DeformMethod::Rbf, DeformMethod::Laplacian}, deformMethodName, parseDeformMethod);
  expectRoundTrip({RbfKernel::Exp, RbfKernel::Gaussian, RbfKernel::Biharmonic, RbfKernel::ThinPlate}, rbfKernelName,
                  parseRbfKernel);
}

TEST(EnumTable, NamesWithoutAParseKeepTheirSpelling)
{
  EXPECT_EQ(sampleOperationName(SampleOperation::Smoothed), "smoothed");
  EXPECT_EQ(sampleOriginName(static_cast<SampleOrigin>(200)), "measured");  // a byte read from a file
  EXPECT_EQ(unfilledCauseName(UnfilledCause::None), "");
  EXPECT_EQ(unfilledCauseName(UnfilledCause::TooLong), "too_long");
  EXPECT_EQ(formatName(TakeFormat::Bvh), "bvh");
  EXPECT_EQ(formatFromPath("take.C3D"), TakeFormat::C3d);
  EXPECT_EQ(parseLengthUnit(" Millimetres "), LengthUnit::Millimetre);
  EXPECT_EQ(unitName(static_cast<LengthUnit>(9)), "mm");
}

} // namespace
} // namespace mocap
