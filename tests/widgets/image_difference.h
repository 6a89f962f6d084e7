#pragma once

#include <QImage>
#include <QRect>
#include <QString>

#include <gtest/gtest.h>

namespace mocap::test {

/// A pixel differs when one of its colour channels differs by more than this (0–255). Renders of
/// one scene under llvmpipe differ by at most a few levels on anti-aliased edges; an erased
/// marker changes its disc by well over a hundred.
inline constexpr int kChannelTolerance = 24;
/// Two renders match when at most this fraction of their pixels differ: 0.01 % is 17 pixels of a
/// 480 × 360 view, where the smallest marker disc covers about 80.
inline constexpr double kMaxDifferingFraction = 0.0001;

/// How two renders differ, pixel by pixel.
struct ImageDifference
{
  bool sizesDiffer = false;
  qsizetype differing = 0;  // pixels with a channel off by more than kChannelTolerance
  qsizetype total = 0;
  QRect bounds;  // the smallest rectangle holding every differing pixel; null when none differ

  [[nodiscard]] double fraction() const { return total > 0 ? double(differing) / double(total) : 1.0; }
  /// Same size and at most kMaxDifferingFraction of the pixels differ.
  [[nodiscard]] bool matches() const { return !sizesDiffer && fraction() <= kMaxDifferingFraction; }
};

/// Compares the colour channels of two renders (alpha ignored).
[[nodiscard]] ImageDifference compareImages(const QImage& actual, const QImage& expected);

/// `actual` dimmed to grey with the pixels that differ from `expected` in magenta, to look at.
[[nodiscard]] QImage highlightDifferences(const QImage& actual, const QImage& expected);

/// Whether `actual` matches `expected`. The render is always written to
/// MOCAP_BUILD_DIR/`name`.actual.png; on a mismatch the highlighted difference goes to
/// `name`.diff.png beside it and the message names both files and says how many pixels differ.
[[nodiscard]] ::testing::AssertionResult matchesImage(const QImage& actual, const QImage& expected, const QString& name);

/// matchesImage against the committed baseline MOCAP_BASELINE_DIR/`name`.png (refresh a baseline
/// deliberately by copying `name`.actual.png over it).
[[nodiscard]] ::testing::AssertionResult matchesBaseline(const QImage& actual, const QString& name);

/// Where matchesImage writes `name`'s render and its highlighted difference.
[[nodiscard]] QString actualImagePath(const QString& name);
[[nodiscard]] QString differenceImagePath(const QString& name);

} // namespace mocap::test
