#include "panels/retarget_section.h"

#include "commands/edit_retarget_gain_command.h"
#include "dialogs/retarget_map_chooser.h"
#include "document/blendshape_solve_model.h"
#include "document/retarget_map_model.h"
#include "document/take_document.h"
#include "panels/status_line.h"
#include "views/mapped_curve_plot.h"

#include "mocap/io/retarget_map_io.h"
#include "mocap/io/shipped_retarget_maps.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

namespace {

enum Column : int
{
  kChannel = 0,
  kSource,
  kGain,
  kPeak,
  kColumns,
};

QTableWidgetItem* readOnlyItem(const QString& text)
{
  auto* item = new QTableWidgetItem(text);
  item->setFlags(item->flags() & ~Qt::ItemIsEditable);
  return item;
}

QString number(double value)
{
  return QLocale().toString(value, 'g', 6);
}

} // namespace

RetargetSection::RetargetSection(TakeDocument& document, BlendshapeSolveModel& solve, RetargetMapModel& map,
                                 QWidget* parent)
    : QGroupBox(tr("Retarget"), parent), m_document(document), m_solve(solve), m_map(map)
{
  auto* rows = new QVBoxLayout(this);
  auto* top = new QHBoxLayout;  // the map row; Save Map As… below the table
  m_chooser = new RetargetMapChooser(tr("No map"), this);
  m_save = new QPushButton(tr("Save Map As…"), this);
  m_save->setToolTip(tr("The map with its edited gains as JSON, for Export Rig and mocap solve --map"));
  top->addWidget(m_chooser, 1);
  rows->addLayout(top);
  m_table = new QTableWidget(0, kColumns, this);
  m_table->setObjectName(QStringLiteral("retargetTable"));
  m_table->setHorizontalHeaderLabels({tr("Channel"), tr("Source"), tr("Gain"), tr("Peak")});
  m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  m_table->verticalHeader()->setVisible(false);
  m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_table->setSelectionMode(QAbstractItemView::SingleSelection);
  m_table->setMinimumHeight(100);
  rows->addWidget(m_table, 1);
  m_plot = new MappedCurvePlot(this);
  rows->addWidget(m_plot);
  m_status = new QLabel(this);
  m_status->setWordWrap(true);
  rows->addWidget(m_status);
  auto* saveRow = new QHBoxLayout;
  saveRow->addWidget(m_save);
  saveRow->addStretch();
  rows->addLayout(saveRow);

  connect(m_chooser, &RetargetMapChooser::changed, this, [this] {
    if (!m_chooser->lacksFile())
      (void)loadMap(m_chooser->map());
  });
  connect(m_save, &QPushButton::clicked, this, &RetargetSection::saveDialog);
  connect(m_table, &QTableWidget::cellChanged, this, &RetargetSection::onItemChanged);
  connect(m_table, &QTableWidget::itemSelectionChanged, this, &RetargetSection::showSelectedCurve);
  connect(&m_map, &RetargetMapModel::mapChanged, this, &RetargetSection::fillTable);
  connect(&m_map, &RetargetMapModel::mapChanged, this, &RetargetSection::showMapChoice);
  connect(&m_map, &RetargetMapModel::gainChanged, this, &RetargetSection::onGainChanged);
  for (const auto signal : {&BlendshapeSolveModel::resultChanged, &BlendshapeSolveModel::rigChanged})
    connect(&m_solve, signal, this, &RetargetSection::updateMapped);
  connect(&m_solve, &BlendshapeSolveModel::weightsEdited, this, &RetargetSection::updateMapped);
  fillTable();
  showMapChoice();  // a map the session already holds
}

QString RetargetSection::loadMap(const std::optional<std::string>& nameOrPath)
{
  if (!nameOrPath) {
    m_map.setMap(std::nullopt, {});
    return {};
  }
  try {
    m_map.setMap(readRetargetMapByNameOrPath(*nameOrPath), QString::fromStdString(*nameOrPath));
  } catch (const std::exception& e) {
    showStatus(tr("Cannot read the map: %1").arg(QString::fromStdString(e.what())), true);
    return m_status->text();
  }
  return {};
}

QString RetargetSection::saveMap(const QString& path)
{
  if (!m_map.map())
    return tr("Load a map first.");
  try {
    writeRetargetMap(path.toStdString(), *m_map.map());
  } catch (const std::exception& e) {
    showStatus(tr("Cannot write the map: %1").arg(QString::fromStdString(e.what())), true);
    return m_status->text();
  }
  m_map.markSaved(path);
  {
    const QSignalBlocker blocker(m_chooser);  // the saved file is the map shown: no reload
    m_chooser->setMap(path);
  }
  showStatus(tr("Saved the map to %1.").arg(path), false);
  return {};
}

QString RetargetSection::setGain(int row, double gain)
{
  if (row < 0 || row >= static_cast<int>(m_rows.size()) || m_rows[static_cast<std::size_t>(row)].second < 0)
    return tr("That row has no source to scale.");
  if (!std::isfinite(gain))
    return tr("A gain must be a number.");
  const auto [channel, source] = m_rows[static_cast<std::size_t>(row)];
  const RetargetChannel& edited = m_map.map()->channels[static_cast<std::size_t>(channel)];
  m_document.undoStack()->push(new EditRetargetGainCommand(
      m_map, channel, source, gain,
      tr("Gain of %1 in %2").arg(QString::fromStdString(edited.sources[static_cast<std::size_t>(source)].shape),
                                 QString::fromStdString(edited.name))));
  return {};
}

void RetargetSection::selectRow(int row)
{
  m_table->selectRow(row);
  showSelectedCurve();
}

QString RetargetSection::statusText() const
{
  return m_status->text();
}

void RetargetSection::showMapChoice()
{
  // A map set on the model elsewhere (a recovered session's) is named in the chooser, not read again.
  if (QString::fromStdString(m_chooser->map().value_or(std::string())) == m_map.name())
    return;
  const QSignalBlocker blocker(m_chooser);
  m_chooser->setMap(m_map.name());
}

void RetargetSection::fillTable()
{
  m_filling = true;
  m_rows.clear();
  m_table->setRowCount(0);
  if (const std::optional<RetargetMap>& map = m_map.map()) {
    for (std::size_t c = 0; c < map->channels.size(); ++c) {
      const RetargetChannel& channel = map->channels[c];
      const int sources = std::max<int>(1, static_cast<int>(channel.sources.size()));
      for (int s = 0; s < sources; ++s) {
        const bool none = channel.sources.empty();
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_rows.emplace_back(static_cast<int>(c), none ? -1 : s);
        m_table->setItem(row, kChannel, readOnlyItem(QString::fromStdString(channel.name)));
        m_table->setItem(row, kSource,
                         readOnlyItem(none ? tr("(none)") : QString::fromStdString(channel.sources[static_cast<std::size_t>(s)].shape)));
        m_table->setItem(row, kGain, none ? readOnlyItem(QString())
                                          : new QTableWidgetItem(number(channel.sources[static_cast<std::size_t>(s)].gain)));
        m_table->setItem(row, kPeak, readOnlyItem(QString()));
      }
    }
  }
  m_save->setEnabled(m_map.map().has_value());
  m_filling = false;
  updateMapped();
}

void RetargetSection::updateMapped()
{
  m_mapped.reset();
  const std::optional<RetargetMap>& map = m_map.map();
  if (!map) {
    showStatus(tr("Load a map to see the solve under a target rig's channels."), false);
  } else if (!m_solve.hasRig()) {
    showStatus(tr("%n channel(s). Load a rig to map its curves.", nullptr, static_cast<int>(map->channels.size())), false);
  } else {
    try {
      const Eigen::MatrixXd none(0, m_solve.rig()->shapeCount());
      m_mapped = applyRetargetMap(*map, m_solve.rig()->shapeNames(), m_solve.hasResult() ? m_solve.weights() : none);
      showStatus(tr("%n channel(s) from the rig's shapes.", nullptr, static_cast<int>(map->channels.size())), false);
    } catch (const std::exception& e) {
      showStatus(tr("The map does not fit the rig: %1").arg(QString::fromStdString(e.what())), true);
    }
  }
  m_filling = true;
  for (int row = 0; row < m_table->rowCount(); ++row) {
    const int channel = m_rows[static_cast<std::size_t>(row)].first;
    const bool peak = m_mapped && m_mapped->weights.rows() > 0;
    m_table->item(row, kPeak)->setText(peak ? number(m_mapped->weights.col(channel).maxCoeff()) : QString());
  }
  m_filling = false;
  showSelectedCurve();
}

void RetargetSection::onItemChanged(int row, int column)
{
  if (m_filling || column != kGain)
    return;
  bool ok = false;
  const double gain = QLocale().toDouble(m_table->item(row, column)->text(), &ok);
  const QString why = ok ? setGain(row, gain) : tr("A gain must be a number.");
  if (!why.isEmpty()) {
    onGainChanged(m_rows[static_cast<std::size_t>(row)].first, m_rows[static_cast<std::size_t>(row)].second);
    showStatus(why, true);
  }
}

void RetargetSection::onGainChanged(int channel, int source)
{
  m_filling = true;
  for (int row = 0; row < static_cast<int>(m_rows.size()); ++row)
    if (m_rows[static_cast<std::size_t>(row)] == std::make_pair(channel, source) && source >= 0)
      m_table->item(row, kGain)->setText(
          number(m_map.map()->channels[static_cast<std::size_t>(channel)].sources[static_cast<std::size_t>(source)].gain));
  m_filling = false;
  updateMapped();
}

void RetargetSection::showSelectedCurve()
{
  const QList<QTableWidgetItem*> selected = m_table->selectedItems();
  if (!m_mapped || m_mapped->weights.rows() == 0 || selected.isEmpty()) {
    m_plot->clear();
    return;
  }
  const auto [channel, source] = m_rows[static_cast<std::size_t>(selected.front()->row())];
  const RetargetChannel& mappedChannel = m_map.map()->channels[static_cast<std::size_t>(channel)];
  Eigen::VectorXd sourceCurve;
  if (source >= 0) {
    const std::vector<std::string> names = m_solve.rig()->shapeNames();
    const auto found = std::find(names.begin(), names.end(), mappedChannel.sources[static_cast<std::size_t>(source)].shape);
    sourceCurve = m_solve.weights().col(found - names.begin());  // applyRetargetMap found it
  }
  m_plot->setCurves(m_mapped->weights.col(channel), std::move(sourceCurve), QString::fromStdString(mappedChannel.name));
}

void RetargetSection::saveDialog()
{
  const QString path = QFileDialog::getSaveFileName(this, tr("Save Retarget Map"), m_map.name(),
                                                    tr("Retarget maps (*.json)"));
  if (!path.isEmpty())
    (void)saveMap(path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive) ? path : path + QStringLiteral(".json"));
}

void RetargetSection::showStatus(const QString& text, bool error)
{
  showStatusLine(*m_status, text, error);
}

} // namespace mocap::ui
