#pragma once

#include <QStringList>
#include <QWidget>

#include <vector>

class QListWidget;
class QTextBrowser;

namespace mocap::ui {

/// Help ▸ Manual: the README's user sections (the studio, the command line), bundled in the
/// program at build time as ":/manual/manual.md" with their pictures, shown with a list of
/// contents. Works offline and always matches the program it came with.
class ManualWindow : public QWidget
{
  Q_OBJECT

public:
  explicit ManualWindow(QWidget* parent = nullptr);

  /// The section headings in reading order (what the contents list shows).
  [[nodiscard]] QStringList headings() const;
  /// Scrolls the text to heading `index` of headings().
  void showHeading(int index);
  [[nodiscard]] QTextBrowser* browser() const { return m_browser; }

private:
  void load();
  /// Pictures wider than the text column are shown at its width (a screenshot is 1280 px wide).
  void fitImages(int width);

  QTextBrowser* m_browser = nullptr;
  QListWidget* m_contents = nullptr;
  std::vector<int> m_headingPositions;  // document position of each heading
};

} // namespace mocap::ui
