#include "document/retarget_map_model.h"

#include "mocap/base/error.h"

#include <cmath>

namespace mocap::ui {

RetargetMapModel::RetargetMapModel(QObject* parent) : QObject(parent) {}

void RetargetMapModel::setMap(std::optional<RetargetMap> map, QString name, bool edited)
{
  m_map = std::move(map);
  m_name = std::move(name);
  m_edited = m_map && edited;
  ++m_generation;
  emit mapChanged();
}

void RetargetMapModel::markSaved(QString name)
{
  m_name = std::move(name);
  m_edited = false;
}

double RetargetMapModel::swapGain(int channel, int source, double gain)
{
  if (!m_map || channel < 0 || channel >= static_cast<int>(m_map->channels.size()))
    throw InvalidArgument("gain edit of a channel the retarget map does not have");
  std::vector<RetargetSource>& sources = m_map->channels[static_cast<std::size_t>(channel)].sources;
  if (source < 0 || source >= static_cast<int>(sources.size()))
    throw InvalidArgument("gain edit of a source the retarget map's channel does not have");
  if (!std::isfinite(gain))
    throw InvalidArgument("a retarget gain must be a finite number");
  double& stored = sources[static_cast<std::size_t>(source)].gain;
  const double before = stored;
  stored = gain;
  m_edited = true;
  emit gainChanged(channel, source);
  return before;
}

} // namespace mocap::ui
