#include "dialogs/manual_window.h"

#include <QFile>
#include <QHBoxLayout>
#include <QImage>
#include <QListWidget>
#include <QSplitter>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextFragment>
#include <QTextImageFormat>

namespace mocap::ui {

namespace {

constexpr int kImageWidth = 720;  // px: readable beside the contents list on a 1280-wide screen

} // namespace

ManualWindow::ManualWindow(QWidget* parent)
    : QWidget(parent, Qt::Window)
{
  setObjectName(QStringLiteral("manualWindow"));
  setWindowTitle(tr("Mocap Studio Manual"));
  m_contents = new QListWidget(this);
  m_contents->setObjectName(QStringLiteral("manualContents"));
  m_browser = new QTextBrowser(this);
  m_browser->setObjectName(QStringLiteral("manualText"));
  m_browser->setOpenExternalLinks(true);
  // Pictures are named as in the README ("docs/images/…"), found under the bundled prefix.
  m_browser->setSearchPaths({QStringLiteral(":/manual")});
  auto* splitter = new QSplitter(this);
  splitter->addWidget(m_contents);
  splitter->addWidget(m_browser);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({220, 780});
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(splitter);
  connect(m_contents, &QListWidget::currentRowChanged, this, &ManualWindow::showHeading);
  load();
  resize(1000, 700);
}

void ManualWindow::load()
{
  QFile file(QStringLiteral(":/manual/manual.md"));
  if (!file.open(QIODevice::ReadOnly)) {
    m_browser->setPlainText(tr("The manual is not part of this build (:/manual/manual.md is missing)."));
    return;
  }
  m_browser->setMarkdown(QString::fromUtf8(file.readAll()));
  fitImages(kImageWidth);
  // Headings of the first three levels make the contents, indented by level. O(#blocks).
  for (QTextBlock block = m_browser->document()->begin(); block.isValid(); block = block.next()) {
    const int level = block.blockFormat().headingLevel();
    if (level < 1 || level > 3)
      continue;
    m_headingPositions.push_back(block.position());
    m_contents->addItem(QString(2 * (level - 1), QLatin1Char(' ')) + block.text());
  }
}

void ManualWindow::fitImages(int width)
{
  // Collected first: changing a fragment's format while walking the fragments would split them.
  struct Picture
  {
    int position = 0;
    int length = 0;
    QTextImageFormat format;
  };
  std::vector<Picture> pictures;
  QTextDocument* document = m_browser->document();
  for (QTextBlock block = document->begin(); block.isValid(); block = block.next())
    for (auto it = block.begin(); !it.atEnd(); ++it)
      if (const QTextFragment fragment = it.fragment(); fragment.isValid() && fragment.charFormat().isImageFormat())
        pictures.push_back({fragment.position(), fragment.length(), fragment.charFormat().toImageFormat()});
  for (Picture& picture : pictures) {
    const QImage image(QStringLiteral(":/manual/") + picture.format.name());
    if (image.isNull() || image.width() <= width)
      continue;
    picture.format.setWidth(width);
    picture.format.setHeight(static_cast<double>(image.height()) * width / image.width());
    QTextCursor cursor(document);
    cursor.setPosition(picture.position);
    cursor.setPosition(picture.position + picture.length, QTextCursor::KeepAnchor);
    cursor.setCharFormat(picture.format);
  }
}

QStringList ManualWindow::headings() const
{
  QStringList names;
  for (int i = 0; i < m_contents->count(); ++i)
    names << m_contents->item(i)->text().trimmed();
  return names;
}

void ManualWindow::showHeading(int index)
{
  if (index < 0 || static_cast<std::size_t>(index) >= m_headingPositions.size())
    return;
  QTextCursor cursor(m_browser->document());
  cursor.setPosition(m_headingPositions[static_cast<std::size_t>(index)]);
  m_browser->setTextCursor(cursor);
  // Heading at the top of the view, not merely somewhere in it.
  m_browser->moveCursor(QTextCursor::End);
  m_browser->setTextCursor(cursor);
  m_browser->ensureCursorVisible();
}

} // namespace mocap::ui
