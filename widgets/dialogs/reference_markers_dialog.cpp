#include "dialogs/reference_markers_dialog.h"

#include "document/take_document.h"

#include "mocap/cleaning/head_stabilization.h"
#include "mocap/model/marker_points.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStringList>
#include <QVBoxLayout>

#include <algorithm>

namespace mocap::ui {

namespace {

/// For a take without a set, the proposal the window's bar shows starts checked (OK accepts it).
bool isProposed(const TakeDocument& document, Eigen::Index marker)
{
  const std::vector<Eigen::Index>& proposed = document.proposedReferenceMarkers();
  return document.referenceMarkers().empty() && std::binary_search(proposed.begin(), proposed.end(), marker);
}

} // namespace

ReferenceMarkersDialog::ReferenceMarkersDialog(const TakeDocument& document, QWidget* parent)
    : QDialog(parent), m_document(document)
{
  setWindowTitle(tr("Reference Markers"));
  auto* layout = new QVBoxLayout(this);
  auto* intro = new QLabel(tr("Head-mounted markers that move only with the head (at least three). Head "
                              "stabilization, the head-stabilized view, layout planning and the face mesh "
                              "remove the head's motion with them; layout planning leaves them out."),
                           this);
  intro->setWordWrap(true);
  layout->addWidget(intro);

  m_list = new QListWidget(this);
  m_list->setObjectName(QStringLiteral("referenceMarkerList"));
  const Take& take = document.take();
  for (Eigen::Index m = 0; m < take.markerCount(); ++m) {
    auto* item = new QListWidgetItem(QString::fromStdString(take.label(m)), m_list);
    item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    item->setCheckState(document.isReferenceMarker(m) || isProposed(document, m) ? Qt::Checked : Qt::Unchecked);
    const double present = take.frameCount() > 0 ? 100.0 * static_cast<double>(take.valid().col(m).count()) /
                                                       static_cast<double>(take.frameCount())
                                                 : 0.0;
    item->setToolTip(tr("Valid in %1 % of the frames").arg(present, 0, 'f', 1));
    if (!isMarker(take, m)) {  // an angle or a force has no place on the head
      item->setFlags(Qt::ItemIsUserCheckable);
      item->setToolTip(tr("A model output, not a marker"));
    }
  }
  layout->addWidget(m_list, 1);

  auto* tools = new QHBoxLayout;
  auto* guess = new QPushButton(tr("&Guess"), this);
  guess->setToolTip(tr("Markers named root… or head…, else the markers that move together as one rigid body"));
  auto* fromSelection = new QPushButton(tr("Use &Selection"), this);
  fromSelection->setEnabled(!document.selection().empty());
  auto* clear = new QPushButton(tr("C&lear"), this);
  clear->setToolTip(tr("No reference markers: head motion is not removed anywhere"));
  tools->addWidget(guess);
  tools->addWidget(fromSelection);
  tools->addWidget(clear);
  tools->addStretch();
  layout->addLayout(tools);
  connect(guess, &QPushButton::clicked, this, [this] { setChosen(guessHeadReferenceMarkers(m_document.take())); });
  connect(fromSelection, &QPushButton::clicked, this, [this] { setChosen(m_document.selection()); });
  connect(clear, &QPushButton::clicked, this, [this] { setChosen({}); });

  m_summary = new QLabel(this);
  m_summary->setWordWrap(true);
  layout->addWidget(m_summary);
  m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  layout->addWidget(m_buttons);
  connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(m_list, &QListWidget::itemChanged, this, &ReferenceMarkersDialog::updateSummary);
  updateSummary();
  resize(380, 520);
}

std::vector<Eigen::Index> ReferenceMarkersDialog::chosen() const
{
  std::vector<Eigen::Index> markers;
  for (int row = 0; row < m_list->count(); ++row)
    if (m_list->item(row)->checkState() == Qt::Checked)
      markers.push_back(row);
  return markers;
}

void ReferenceMarkersDialog::setChosen(const std::vector<Eigen::Index>& markers)
{
  for (int row = 0; row < m_list->count(); ++row)
    m_list->item(row)->setCheckState(std::find(markers.begin(), markers.end(), row) != markers.end() ? Qt::Checked
                                                                                                     : Qt::Unchecked);
  updateSummary();
}

void ReferenceMarkersDialog::updateSummary()
{
  const std::vector<Eigen::Index> markers = chosen();
  const bool usable = markers.empty() || markers.size() >= 3;
  QStringList labels;
  for (const Eigen::Index m : markers)
    labels << m_list->item(static_cast<int>(m))->text();
  if (markers.empty())
    m_summary->setText(tr("No reference markers: head motion is not removed, and layout planning plans every "
                          "labelled marker."));
  else if (!usable)
    m_summary->setText(tr("%1: a head pose needs at least three markers (or none).").arg(labels.join(QStringLiteral(", "))));
  else
    m_summary->setText(tr("%n reference marker(s): %1", nullptr, static_cast<int>(markers.size()))
                           .arg(labels.join(QStringLiteral(", "))));
  m_summary->setStyleSheet(usable ? QString() : QStringLiteral("color: #c0392b;"));
  m_buttons->button(QDialogButtonBox::Ok)->setEnabled(usable);
}

} // namespace mocap::ui
