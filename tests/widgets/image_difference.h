#pragma once

#include <QImage>
#include <QRect>
#include <QString>

#include <gtest/gtest.h>

namespace mocap::test {

/// A pixel differs when one of its colour channels differs by more than this (0–255): room for
/// rounding between renderer builds (llvmpipe under Xvfb renders one scene identically run after
/// run) and small shade changes, while a marker's white disc stands 90–200 levels off the
/// background or the grey mesh behind it.
inline constexpr int kChannelTolerance = 24;
/// Two renders match when at most this fraction of their pixels differ: 0.01 % is 17 pixels of
/// a 480 × 360 view, where erasing a marker changes at least 53 (one half under a label).
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
/// build/tests/`name`.actual.png; on a mismatch the highlighted difference goes to
/// `name`.diff.png beside it and the message names both files and says how many pixels differ.
[[nodiscard]] ::testing::AssertionResult matchesImage(const QImage& actual, const QImage& expected, const QString& name);

/// matchesImage against the committed baseline tests/baselines/`name`.png (refresh a baseline
/// deliberately by copying `name`.actual.png over it).
[[nodiscard]] ::testing::AssertionResult matchesBaseline(const QImage& actual, const QString& name);

/// Where matchesImage writes `name`'s render and its highlighted difference.
[[nodiscard]] QString actualImagePath(const QString& name);
[[nodiscard]] QString differenceImagePath(const QString& name);

} // namespace mocap::test
