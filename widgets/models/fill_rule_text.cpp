#include "models/fill_rule_text.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace mocap::ui {

QString secondsText(double seconds)
{
  return QCoreApplication::translate("FillRuleText", "%1 s").arg(QString::number(seconds, 'g', 4));
}

QString fillRuleText(const GapFillReport& report, const Take& take, const FillOptions& options)
{
  switch (report.cause) {
  case UnfilledCause::TooLong:
    if (options.maxGap > 0) {
      const auto frames = static_cast<int>(options.maxGap);  // a plain variable, so lupdate sees the plural
      return QCoreApplication::translate("FillRuleText", "over the %n-frame limit", nullptr, frames);
    }
    return QCoreApplication::translate("FillRuleText", "over the %1 limit").arg(secondsText(options.maxGapSeconds));
  case UnfilledCause::EdgeGap:
    return report.gap.firstFrame == 0
               ? QCoreApplication::translate("FillRuleText", "at the take's start: no extrapolation")
               : QCoreApplication::translate("FillRuleText", "at the take's end: no extrapolation");
  case UnfilledCause::RarelyValid: {
    const double seen = 100.0 * static_cast<double>(take.valid().col(report.gap.marker).count()) /
                        static_cast<double>(std::max<Eigen::Index>(take.frameCount(), 1));
    return QCoreApplication::translate("FillRuleText", "marker seen in %1 % of the take")
        .arg(QString::number(std::round(10.0 * seen) / 10.0));
  }
  case UnfilledCause::NeverValid: return QCoreApplication::translate("FillRuleText", "marker never seen");
  case UnfilledCause::ModelOutput: return QCoreApplication::translate("FillRuleText", "a model output, not a marker");
  case UnfilledCause::Method:
  case UnfilledCause::None: break;
  }
  return QString::fromStdString(report.reason);
}

} // namespace mocap::ui
