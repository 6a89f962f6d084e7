#pragma once

#include <Eigen/Core>

#include <QLabel>

#include <utility>

namespace mocap::ui {

class TakeDocument;

/// The status bar's "Frame 63 of 63–555 — 2 markers selected": the current frame in the file's
/// numbering and the selection's size, following the document. Sized once per take for its
/// widest line (fixLabelSizeFor), so scrubbing never relayouts the window. O(1) per change.
class FrameStatusLabel final : public QLabel
{
  Q_OBJECT

public:
  explicit FrameStatusLabel(const TakeDocument& document, QWidget* parent = nullptr);

private:
  void showFrame();
  [[nodiscard]] QString lineFor(Eigen::Index frame, std::size_t selected) const;

  const TakeDocument& m_document;
  std::pair<Eigen::Index, Eigen::Index> m_fitsTake{-1, -1};  // frames, markers the size fits
};

} // namespace mocap::ui
