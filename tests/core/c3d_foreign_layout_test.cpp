// Files from other vendors' systems whose header and parameters disagree (issue 30): the reader
// picks the layout the file's bytes can hold, says which and why, and never reads the wrong bytes
// silently. Each test builds a small file with our writer and breaks one thing the way a foreign
// writer did.
#include "foreign_takes.h"
#include "test_support.h"

#include "mocap/base/error.h"
#include "mocap/base/file_io.h"
#include "mocap/io/c3d_reader.h"
#include "mocap/model/data_loss_record.h"
#include "mocap/io/c3d_writer.h"
#include "mocap/model/gaps.h"
#include "mocap/model/marker_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace mocap {
namespace {

constexpr std::size_t kBlock = 512;

struct Read
{
  Take take;
  std::vector<std::string> warnings;
  std::vector<std::string> dataLoss;
  C3dLayoutReport layout;
};

Read parse(const std::string& bytes)
{
  Read read;
  read.take = parseC3d(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "foreign.c3d",
                       &read.warnings, &read.dataLoss, &read.layout);
  return read;
}

/// The warning that contains every one of `parts`, or "" (the list is printed on failure).
std::string warningWith(const Read& read, const std::vector<std::string>& parts)
{
  for (const std::string& w : read.warnings)
    if (std::all_of(parts.begin(), parts.end(), [&](const std::string& p) { return w.find(p) != std::string::npos; }))
      return w;
  std::string all;
  for (const std::string& w : read.warnings)
    all += "\n  " + w;
  ADD_FAILURE() << "no warning with '" << parts.front() << "'... among:" << all;
  return {};
}

bool anyWarningWith(const Read& read, const std::string& part)
{
  return std::any_of(read.warnings.begin(), read.warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

/// The same samples, validity and analog values (positions exactly: both come from one file).
void expectSameData(const Take& expected, const Take& actual)
{
  ASSERT_EQ(expected.labels(), actual.labels());
  ASSERT_EQ(expected.frameCount(), actual.frameCount());
  EXPECT_TRUE((expected.valid() == actual.valid()).all());
  for (Eigen::Index m = 0; m < expected.markerCount(); ++m)
    EXPECT_TRUE(expected.trajectory(m) == actual.trajectory(m)) << expected.label(m);
  ASSERT_EQ(expected.analog().sampleCount(), actual.analog().sampleCount());
  ASSERT_EQ(expected.analog().channelCount(), actual.analog().channelCount());
  EXPECT_EQ(expected.analog().stored, actual.analog().stored);
}

// --- Editing the bytes our writer produces (Intel, float storage) ---

std::size_t dataStart(const std::string& bytes)
{
  std::uint16_t block = 0;
  std::memcpy(&block, bytes.data() + 16, 2);  // header word 9
  return (block - std::size_t{1}) * kBlock;
}

void putWord(std::string& bytes, std::size_t at, int value)
{
  const auto word = static_cast<std::uint16_t>(static_cast<std::int16_t>(value));
  std::memcpy(&bytes[at], &word, 2);
}

void putFloat(std::string& bytes, std::size_t at, float value)
{
  std::memcpy(&bytes[at], &value, 4);
}

/// Byte offset of the value of parameter GROUP:NAME, found by walking the records.
std::size_t valueAt(const std::string& bytes, const std::string& group, const std::string& name)
{
  std::map<int, std::string> groups;
  std::size_t pos = (static_cast<unsigned char>(bytes[0]) - std::size_t{1}) * kBlock + 4;
  while (pos + 2 < bytes.size()) {
    const auto length = static_cast<std::size_t>(std::abs(static_cast<signed char>(bytes[pos])));
    const int id = static_cast<signed char>(bytes[pos + 1]);
    if (length == 0 || id == 0)
      break;
    const std::string record = bytes.substr(pos + 2, length);
    const std::size_t linkAt = pos + 2 + length;
    std::int16_t link = 0;
    std::memcpy(&link, bytes.data() + linkAt, 2);
    if (id < 0)
      groups[-id] = record;
    else if (groups[id] == group && record == name)
      return linkAt + 4 + static_cast<unsigned char>(bytes[linkAt + 3]);  // type, dimension count, dimensions
    if (link <= 0)
      break;
    pos = linkAt + static_cast<std::size_t>(link);
  }
  ADD_FAILURE() << "no parameter " << group << ":" << name;
  return 0;
}

void putIntParameter(std::string& bytes, const std::string& group, const std::string& name, int value)
{
  putWord(bytes, valueAt(bytes, group, name), value);
}

void putFloatParameter(std::string& bytes, const std::string& group, const std::string& name, float value)
{
  putFloat(bytes, valueAt(bytes, group, name), value);
}

std::size_t frameBytes(int markers, int analogValues)
{
  return static_cast<std::size_t>(markers * 4 + analogValues) * 4;
}

TEST(C3dForeignLayout, DataStartInsideTheHeaderOrParametersIsNotUsed)
{
  const std::string bytes = encodeC3d(test::distinctValuesTake(3, 20, 2, 2));
  const Read reference = parse(bytes);
  ASSERT_TRUE(reference.warnings.empty()) << reference.warnings.front();
  const std::size_t dataBlock = dataStart(bytes) / kBlock + 1;
  for (const auto& [block, section] : {std::pair{1, "header"}, std::pair{2, "parameter section"}}) {
    SCOPED_TRACE(block);
    std::string copy = bytes;
    putIntParameter(copy, "POINT", "DATA_START", block);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"POINT:DATA_START (block " + std::to_string(block) + ") points into the " + section,
                             "using the header's data start (block " + std::to_string(dataBlock) + ")"});
    EXPECT_EQ(read.layout.dataStartSource, "header");
    EXPECT_EQ(read.layout.dataStartBlock, dataBlock);
  }
  // With both pointers unusable the file cannot be read, and the error says why.
  std::string copy = bytes;
  putIntParameter(copy, "POINT", "DATA_START", 2);
  putWord(copy, 16, 1);
  try {
    (void)parse(copy);
    FAIL() << "read a file whose data pointers both point into its header and parameters";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("no usable data section start: POINT:DATA_START (block 2) points into the "
                                         "parameter section and the header's data start (block 1) points into the "
                                         "header"),
              std::string::npos)
        << e.what();
  }
}

TEST(C3dForeignLayout, DataStartOneBlockOffLosesToTheOneThatFits)
{
  const std::string bytes = encodeC3d(test::distinctValuesTake(3, 20, 2, 2));
  const Read reference = parse(bytes);
  const auto dataBlock = static_cast<int>(dataStart(bytes) / kBlock + 1);
  {
    SCOPED_TRACE("POINT:DATA_START one block late");
    std::string copy = bytes;
    putIntParameter(copy, "POINT", "DATA_START", dataBlock + 1);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"disagree; using the header's data start", "holds the 20 declared frames exactly",
                             "holds only"});
    EXPECT_TRUE(read.dataLoss.empty());
  }
  {
    SCOPED_TRACE("the header one block late");
    std::string copy = bytes;
    putWord(copy, 16, dataBlock + 1);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"disagree; using POINT:DATA_START (block " + std::to_string(dataBlock) + ")"});
    EXPECT_EQ(read.layout.dataStartSource, "POINT:DATA_START");
  }
  {
    SCOPED_TRACE("POINT:DATA_START one block early, on an empty block after the parameters");
    std::string copy = bytes;
    copy.insert(dataStart(bytes), kBlock, '\0');
    putWord(copy, 16, dataBlock + 1);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"the header's data start (block " + std::to_string(dataBlock + 1) +
                                 ") and POINT:DATA_START (block " + std::to_string(dataBlock) + ") disagree",
                             "with POINT:DATA_START (block " + std::to_string(dataBlock) +
                                 ") it holds the 20 declared frames and 512 bytes more"});
    EXPECT_EQ(read.layout.dataStartBlock, static_cast<std::size_t>(dataBlock + 1));
  }
}

TEST(C3dForeignLayout, AnalogValuesPerFrameAreCheckedAgainstTheChannels)
{
  const std::string bytes = encodeC3d(test::distinctValuesTake(3, 20, 2, 4));
  const Read reference = parse(bytes);
  ASSERT_EQ(reference.take.analog().stored.rows(), 80);
  {
    SCOPED_TRACE("the header's word 3 is wrong");
    std::string copy = bytes;
    putWord(copy, 4, 4);  // header word 3: 4 analog values per frame instead of 2 × 4
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"the header's analog values per frame (4)",
                             "using ANALOG:USED × ANALOG:RATE / POINT:RATE (2 × 4 = 8)",
                             "holds the 20 declared frames exactly"});
    EXPECT_EQ(read.layout.analogValuesPerFrame, 8u);
    EXPECT_EQ(read.layout.frameBytes, frameBytes(3, 8));
  }
  {
    SCOPED_TRACE("ANALOG:RATE is wrong");
    std::string copy = bytes;
    putFloatParameter(copy, "ANALOG", "RATE", 200.0f);  // says 2 samples per frame
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"using the header's analog values per frame (8)", "(2 × 2 = 4)"});
    (void)warningWith(read, {"ANALOG:RATE (200) is not the frame rate × the 4 analog samples per frame; using 400"});
    EXPECT_DOUBLE_EQ(read.take.analog().rate, 400.0);
  }
}

TEST(C3dForeignLayout, EveryHeaderParameterConflictIsAWarning)
{
  const std::string bytes = encodeC3d(test::distinctValuesTake(3, 20));
  const Read reference = parse(bytes);
  ASSERT_TRUE(reference.warnings.empty()) << reference.warnings.front();
  {
    SCOPED_TRACE("scale");
    std::string copy = bytes;
    putFloat(copy, 12, -2.6f);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"POINT:SCALE (-1) differs from the header's scale (-2.6); using POINT:SCALE"});
    EXPECT_TRUE((read.take.residuals() == reference.take.residuals()).all()) << "residuals use POINT:SCALE";
  }
  {
    SCOPED_TRACE("storage: the header's scale says integers");
    std::string copy = bytes;
    putFloat(copy, 12, 1.0f);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"POINT:SCALE (-1, float storage) and the header's scale (1, integer storage) disagree; "
                             "using POINT:SCALE"});
  }
  {
    SCOPED_TRACE("rate");
    std::string copy = bytes;
    putFloat(copy, 20, 120.0f);
    const Read read = parse(copy);
    EXPECT_DOUBLE_EQ(read.take.frameRate(), 100.0);
    (void)warningWith(read, {"POINT:RATE (100) differs from the header's frame rate (120); using POINT:RATE"});
  }
  {
    SCOPED_TRACE("point count");
    std::string copy = bytes;
    putIntParameter(copy, "POINT", "USED", 2);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"the header's point count (3) and POINT:USED (2) disagree; using the header's"});
  }
  {
    SCOPED_TRACE("frame count");
    std::string copy = bytes;
    putIntParameter(copy, "POINT", "FRAMES", 25);
    const Read read = parse(copy);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"POINT:FRAMES (25) differs from the header's frame count (20)"});
  }
}

TEST(C3dForeignLayout, DataSectionLongerOrShorterThanDeclaredSaysWhich)
{
  const std::string bytes = encodeC3d(test::distinctValuesTake(3, 20));
  const Read reference = parse(bytes);
  const std::size_t frame = frameBytes(3, 0);
  {
    SCOPED_TRACE("longer");
    const std::string longer = bytes + bytes.substr(dataStart(bytes), 10 * frame);
    const Read read = parse(longer);
    expectSameData(reference.take, read.take);
    (void)warningWith(read, {"the data section is longer than declared", "(10 whole frames) follow the 20 declared"});
    EXPECT_FALSE(anyWarningWith(read, "truncated"));
    EXPECT_TRUE(read.dataLoss.empty());
    EXPECT_EQ(read.layout.dataBytes, 30 * frame);
    EXPECT_EQ(read.layout.declaredDataBytes, 20 * frame);
  }
  {
    SCOPED_TRACE("shorter");
    const std::string shorter = bytes.substr(0, bytes.size() - 5 * frame - frame / 2);
    const Read read = parse(shorter);
    EXPECT_EQ(read.take.frameCount(), 14);
    ASSERT_EQ(read.dataLoss.size(), 1u);
    EXPECT_NE(read.dataLoss.front().find("the data section is shorter than declared: it holds 14 of the 20 frames"),
              std::string::npos)
        << read.dataLoss.front();
    EXPECT_FALSE(anyWarningWith(read, "longer"));
  }
}

TEST(C3dForeignLayout, ResidualWordIsTestedAsAnInteger)
{
  // 7 frames: pairs of frames go through the vector path, the last one through the scalar path.
  const Take take = test::distinctValuesTake(1, 7);
  std::string bytes = encodeC3d(take);
  const std::size_t frame = frameBytes(1, 0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float words[] = {-1.0f, -0.5f, 773.0f, 1e9f, 40000.0f, nan, 1e9f};
  for (std::size_t f = 0; f < 7; ++f)
    putFloat(bytes, dataStart(bytes) + f * frame + 12, words[f]);
  const Read read = parse(bytes);
  Eigen::Array<bool, 7, 1> valid;
  valid << false, true, true, false, false, false, false;
  EXPECT_TRUE((read.take.valid().col(0) == valid).all()) << read.take.valid().col(0).transpose();
  EXPECT_EQ(read.take.residuals()(1, 0), 0.0) << "-0.5 converts to the integer 0: valid, residual 0";
  EXPECT_EQ(read.take.residuals()(2, 0), 5.0);  // 773 = 0x0305: residual 5, cameras 3
  EXPECT_EQ(read.take.cameraMasks()(2, 0), 3);
  for (Eigen::Index f : {0, 3, 4, 5, 6}) {
    EXPECT_EQ(read.take.residuals()(f, 0), -1.0) << "frame " << f << ": no residual made up";
    EXPECT_EQ(read.take.cameraMasks()(f, 0), 0) << "frame " << f;
  }
  // 40000 is a 16-bit word with its sign bit set (as 65535 is −1): invalid as the format says. 1e9
  // and NaN are no 16-bit word at all.
  (void)warningWith(read, {"3 sample(s) have a residual word that is no 16-bit integer"});
}

TEST(C3dForeignLayout, IntegerCoordinatesThatWrapRoundAreReportedAsWrongData)
{
  // A real integer file (Intel, scale 0.0833) whose first always-seen marker is made to move
  // smoothly past 32767 × scale on x, as an ART file's head marker did: the stored words wrap
  // round and the curve jumps by 65536 × scale, which the reader must not pass off as motion.
  const std::filesystem::path path = test::dataFile("c3d/sample01/Eb015pi.c3d");
  std::string bytes = readFileBytes(path);
  const Read original = parse(bytes);
  ASSERT_FALSE(original.layout.isFloat);
  EXPECT_FALSE(anyWarningWith(original, "16-bit range")) << "the file as recorded has no wrap";
  Eigen::Index marker = 0;
  while (marker < original.take.markerCount() && !original.take.valid().col(marker).all())
    ++marker;
  ASSERT_LT(marker, original.take.markerCount());
  const std::size_t start = (original.layout.dataStartBlock - 1) * kBlock;
  for (Eigen::Index f = 0; f < original.take.frameCount(); ++f)  // x word: 32 000 + 10 per frame
    putWord(bytes, start + static_cast<std::size_t>(f) * original.layout.frameBytes + static_cast<std::size_t>(marker) * 8,
            static_cast<std::int16_t>(static_cast<std::uint16_t>(32000 + 10 * f)));
  const Read wrapped = parse(bytes);
  const std::string& label = original.take.label(marker);
  // 32 000 + 10 f passes 32 767 after index 76: the jump is between the file's frames 77 and 78.
  const std::string frames = " x between frames " + std::to_string(original.take.firstFrame() + 76) + " and " +
                             std::to_string(original.take.firstFrame() + 77);
  ASSERT_EQ(wrapped.dataLoss.size(), 1u);
  EXPECT_NE(wrapped.dataLoss.front().find("1 marker(s) jump by over half the 16-bit range"), std::string::npos)
      << wrapped.dataLoss.front();
  EXPECT_NE(wrapped.dataLoss.front().find(label + frames), std::string::npos) << wrapped.dataLoss.front();
  EXPECT_TRUE((wrapped.take.valid() == original.take.valid()).all()) << "reported, not hidden or repaired";

  // Saved (as float, whose bytes cannot wrap), the finding travels with the take: every later
  // read reports it as data loss, once, however often the take is saved again.
  std::string saved = encodeC3d(wrapped.take);
  for (int save = 0; save < 2; ++save) {
    const Read again = parse(saved);
    ASSERT_TRUE(again.layout.isFloat);
    ASSERT_EQ(again.dataLoss.size(), 1u) << "save " << save;
    EXPECT_EQ(again.dataLoss.front().rfind("recorded when ", 0), 0u) << again.dataLoss.front();
    EXPECT_NE(again.dataLoss.front().find(label + frames), std::string::npos) << again.dataLoss.front();
    EXPECT_EQ(std::count_if(again.take.history().begin(), again.take.history().end(),
                            [](const ProcessingStep& step) { return step.operation == kDataLossOperation; }),
              1);
    saved = encodeC3d(again.take);
  }
}

TEST(C3dForeignLayout, FallbackLabelNeverTakesARealLabel)
{
  Take take = test::distinctValuesTake(3, 5);
  take.setLabel(1, "XX");
  take.setLabel(2, "M2");
  std::string bytes = encodeC3d(take);
  const std::size_t labels = valueAt(bytes, "POINT", "LABELS");
  const std::size_t at = bytes.find("XX", labels);
  ASSERT_LT(at, labels + 6);
  bytes.replace(at, 2, "  ");
  const Read read = parse(bytes);
  EXPECT_EQ(read.take.labels(), (std::vector<std::string>{"P1", "M2_2", "M2"}));
  (void)warningWith(read, {"marker 2 has no label; named M2_2"});
  EXPECT_EQ(read.take.trajectory(2), take.trajectory(2)) << "the real M2 keeps its name and its samples";
}

TEST(C3dForeignLayout, NexusModelOutputsKeepTheirPointTypes)
{
  using T = PointType;
  for (const bool typeGroups : {false, true}) {
    SCOPED_TRACE(typeGroups ? "with POINT:TYPE_GROUPS" : "without POINT:TYPE_GROUPS");
    const std::string bytes = encodeC3d(test::nexusStyleTake(typeGroups));
    const Read read = parse(bytes);
    const std::vector<T> expected = {T::Marker, T::Angle, T::Force, T::Moment, T::Power,
                                     typeGroups ? T::Other : T::Marker, T::Angle};
    EXPECT_EQ(test::pointTypes(read.take), expected);
    EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
    // Written back, the lists say exactly the take's points ("NotInTheTake" is gone) and read to
    // the same types; TYPE_GROUPS is kept as the file had it.
    const std::string again = encodeC3d(read.take);
    const Read back = parse(again);
    EXPECT_EQ(test::pointTypes(back.take), expected);
    const C3dParameterTree& lists = back.take.parameters();
    EXPECT_EQ(lists.strings("POINT", "ANGLES"), (std::vector<std::string>{"LHipAngles", "RHipAngles"}));
    EXPECT_EQ(lists.strings("POINT", "FORCES"), (std::vector<std::string>{"LHipForce"}));
    EXPECT_EQ(lists.strings("POINT", "POWERS"), (std::vector<std::string>{"LHipPower"}));
    EXPECT_EQ(lists.strings("POINT", "TYPE_GROUPS"), read.take.parameters().strings("POINT", "TYPE_GROUPS"));
  }
}

// Plug-in Gait's segment axes and centre of mass are in no model-output list of the file: typed by
// their names only when the points are a segment's axes, said in a warning, and listed when written.
TEST(C3dForeignLayout, PlugInGaitVirtualPointsAreModelOutputs)
{
  for (const char* subject : {"", "Anna:"}) {
    const std::string prefix = subject;
    SCOPED_TRACE("prefix '" + prefix + "'");
    const Read read = parse(encodeC3d(test::plugInGaitTake(prefix)));
    std::vector<std::string> virtuals;
    for (Eigen::Index m = 0; m < read.take.markerCount(); ++m)
      if (read.take.pointType(m) == PointType::Virtual)
        virtuals.push_back(read.take.label(m));
    std::vector<std::string> expected;
    for (const char* name : {"PELO", "PELA", "PELL", "PELP", "CentreOfMass", "CentreOfMassFloor"})
      expected.push_back(prefix + name);
    EXPECT_EQ(virtuals, expected) << "not the femur without its P, nor the tibia whose axes slant";
    EXPECT_EQ(markerLabels(read.take).size(), 3u + 3u + 4u);
    (void)warningWith(read, {"6 points are Vicon Plug-in Gait virtual points", prefix + "PELO, "});
    EXPECT_EQ(describeModelOutputs(read.take), "6 model outputs (6 virtual points)");
    for (const Gap& gap : findGaps(read.take))
      EXPECT_NE(read.take.label(gap.marker), prefix + "PELA") << "a model output's gap is not the take's";

    // Written back, they are listed (POINT:VIRTUALS, named in TYPE_GROUPS) and read to the same
    // types without a guess.
    const Read back = parse(encodeC3d(read.take));
    EXPECT_EQ(test::pointTypes(back.take), test::pointTypes(read.take));
    const C3dParameterTree& lists = back.take.parameters();
    EXPECT_EQ(lists.strings("POINT", "VIRTUALS"), expected);
    const std::vector<std::string> groups = lists.strings("POINT", "TYPE_GROUPS");
    const std::vector<std::string> pair = {"VIRTUALS", "VIRTUAL"};
    EXPECT_NE(std::search(groups.begin(), groups.end(), pair.begin(), pair.end()), groups.end());
    EXPECT_FALSE(anyWarningWith(back, "Plug-in Gait"));
  }
}

TEST(C3dForeignLayout, PlugInGaitNamesAloneTypeNothing)
{
  // A take's own labels that happen to be Plug-in Gait's: four collinear points named like the
  // head's axes, a lone toe origin, a centre of mass in a file without model outputs.
  Take own = test::distinctValuesTake(6, 5);
  const std::vector<std::string> labels = {"CentreOfMass", "HEDO", "HEDA", "HEDL", "HEDP", "LTOO"};
  for (Eigen::Index m = 0; m < own.markerCount(); ++m)
    own.setLabel(m, labels[static_cast<std::size_t>(m)]);
  const Read read = parse(encodeC3d(own));
  EXPECT_EQ(markerLabels(read.take), labels);
  EXPECT_FALSE(anyWarningWith(read, "Plug-in Gait"));

  // Beside the file's listed model outputs, the centre of mass is one.
  Take nexus = test::nexusStyleTake(false);
  const Eigen::Index centre = nexus.addMarker("Anna:CentreOfMass");
  const Read withOutputs = parse(encodeC3d(nexus));
  EXPECT_EQ(withOutputs.take.pointType(centre), PointType::Virtual);
  EXPECT_EQ(withOutputs.take.pointType(0), PointType::Marker) << "LASI";
}

TEST(C3dForeignLayout, PointTypesTravelWithTheMarker)
{
  Take take = parse(encodeC3d(test::nexusStyleTake(false))).take;
  MarkerColumn angles = take.removeMarker(1);
  EXPECT_EQ(angles.type, PointType::Angle);
  EXPECT_EQ(take.pointType(1), PointType::Force);
  take.insertMarker(0, std::move(angles));
  EXPECT_EQ(take.pointType(0), PointType::Angle);
  EXPECT_EQ(take.pointType(1), PointType::Marker);
  EXPECT_EQ(take.pointType(take.addMarker("new")), PointType::Marker);
}

TEST(C3dForeignLayout, RealNexusFileHasItsModelOutputsTyped)
{
  std::vector<std::string> warnings;
  const Take take = readC3d(test::dataFile("c3d/sample03/gait-pig-nz.c3d"), &warnings);
  std::map<PointType, int> counts;
  for (const PointType type : test::pointTypes(take))
    ++counts[type];
  EXPECT_EQ(counts[PointType::Angle], 12);
  EXPECT_EQ(counts[PointType::Force], 8);
  EXPECT_EQ(counts[PointType::Moment], 8);
  EXPECT_EQ(counts[PointType::Power], 6);
  // Plug-in Gait's 9 lower-body segments, 4 points each (PELO… RTOL), in no list of the file.
  EXPECT_EQ(counts[PointType::Virtual], 36);
  EXPECT_EQ(counts[PointType::Marker], 85 - 34 - 36);
  EXPECT_EQ(take.pointType(*take.markerIndex("LHipAngles")), PointType::Angle);
  EXPECT_EQ(take.pointType(*take.markerIndex("LFEO")), PointType::Virtual);
  EXPECT_EQ(take.pointType(*take.markerIndex("RKNE")), PointType::Marker);
  EXPECT_EQ(std::count_if(warnings.begin(), warnings.end(),
                          [](const std::string& w) { return w.find("36 points are Vicon Plug-in Gait") == 0; }),
            1);
  const std::string bytes = encodeC3d(take);
  EXPECT_EQ(test::pointTypes(parse(bytes).take), test::pointTypes(take)) << "written back, the same types";
  // Nexus writes an invalid sample's residual word as 65535.0: the 16-bit word 0xFFFF, −1. The
  // unlabelled "*5" has it in every frame, at the origin.
  EXPECT_FALSE(take.valid().col(*take.markerIndex("*5")).any());
}

// The conformance files whose header and parameters agree read without any layout warning; the
// one real conflict among them is Dance.c3d's POINT:FRAMES (500) against its header (499 frames,
// which its data section holds exactly).
TEST(C3dForeignLayout, ConformanceFilesReportTheirLayoutAndNoFalseConflicts)
{
  const char* const files[] = {"c3d/sample01/Eb015pi.c3d", "c3d/sample01/Eb015pr.c3d", "c3d/sample01/Eb015vr.c3d",
                               "c3d/sample02/sgi_int.c3d", "c3d/sample02/dec_real.c3d", "c3d/sample03/gait-pig-nz.c3d",
                               "c3d/sample08/TESTBPI.c3d", "c3d/sample08/TESTDPI.c3d", "c3d/sample16/basketball.c3d",
                               "c3d/sample00_motion_analysis/Walk1.c3d", "c3d/btk_others/mocap36.c3d",
                               "c3d/sample37/ART-Human_tools_integer_6dofLimbs.c3d"};
  for (const char* file : files) {
    SCOPED_TRACE(file);
    Read read;
    read.take = readC3d(test::dataFile(file), &read.warnings, &read.dataLoss, &read.layout);
    for (const char* conflict : {"disagree", "differs", "longer", "shorter", "ANALOG:RATE", "points into"})
      EXPECT_FALSE(anyWarningWith(read, conflict)) << conflict;
    EXPECT_EQ(read.layout.dataStartSource, "POINT:DATA_START");
    EXPECT_LE(read.layout.declaredDataBytes, read.layout.dataBytes);
    EXPECT_LT(read.layout.dataBytes - read.layout.declaredDataBytes, kBlock);
  }
  Read eb015pr;
  eb015pr.take = readC3d(test::dataFile("c3d/sample01/Eb015pr.c3d"), nullptr, nullptr, &eb015pr.layout);
  EXPECT_EQ(eb015pr.layout.dataStartBlock, 11u);
  EXPECT_TRUE(eb015pr.layout.isFloat);
  EXPECT_EQ(eb015pr.layout.frameBytes, frameBytes(26, 64));
  EXPECT_EQ(eb015pr.layout.analogValuesPerFrame, 64u);
  EXPECT_EQ(eb015pr.layout.declaredFrames, 450u);
  EXPECT_EQ(eb015pr.layout.declaredDataBytes, 450 * frameBytes(26, 64));

  Read dance;
  dance.take = readC3d(test::dataFile("c3d/sample13/Dance.c3d"), &dance.warnings, nullptr, &dance.layout);
  EXPECT_EQ(dance.take.frameCount(), 499);
  (void)warningWith(dance, {"POINT:FRAMES (500) differs from the header's frame count (499)"});
  EXPECT_EQ(dance.layout.dataStartSource, "header");
}

} // namespace
} // namespace mocap
