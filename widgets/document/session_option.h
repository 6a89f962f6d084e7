#pragma once

#include <QObject>
#include <QSettings>
#include <QString>
#include <QVariant>

#include <utility>

namespace mocap::ui {

/// How a SessionOption<T> is kept in QSettings: as a QVariant of T under its key. Specialised
/// for the types kept otherwise (a colour scheme as one colour name per sub-key).
template <typename T>
struct OptionCodec
{
  [[nodiscard]] static T read(const QSettings& settings, const QString& key, const T& fallback)
  {
    return settings.value(key, QVariant::fromValue(fallback)).template value<T>();
  }
  static void write(QSettings& settings, const QString& key, const T& value)
  {
    settings.setValue(key, QVariant::fromValue(value));
  }
};

/// The change signal of one option (a template cannot be a QObject).
class OptionSignal final : public QObject
{
  Q_OBJECT

signals:
  void changed();
};

/// One remembered user setting of type T: read from QSettings once (clamped into its range, as a
/// settings file can be edited by hand), written back on every change, and announced to whoever
/// follows it, so the views and actions follow an option instead of being told by the window.
/// (The shape of Tiled's SessionOption<T>, with the value held and Qt's signal for the callbacks,
/// so a follower's connection ends with it.) Get and set are O(1) plus one QSettings write.
template <typename T>
class SessionOption
{
public:
  using Clamp = T (*)(const T&);

  SessionOption(QString key, T fallback, Clamp clamp = nullptr)
      : m_key(std::move(key)), m_default(std::move(fallback)), m_clamp(clamp)
  {
    m_value = clamped(OptionCodec<T>::read(QSettings(), m_key, m_default));
  }
  SessionOption(const SessionOption&) = delete;
  SessionOption& operator=(const SessionOption&) = delete;

  [[nodiscard]] const T& get() const { return m_value; }
  operator const T&() const { return m_value; }  // NOLINT(google-explicit-constructor): reads like the value
  [[nodiscard]] const QString& key() const { return m_key; }
  [[nodiscard]] const T& defaultValue() const { return m_default; }
  /// Sets the option (clamped), remembers it and tells the followers; false when nothing changed.
  bool set(T value)
  {
    value = clamped(std::move(value));
    if (value == m_value)
      return false;
    m_value = std::move(value);
    QSettings settings;
    OptionCodec<T>::write(settings, m_key, m_value);
    emit m_signal.changed();
    return true;
  }
  /// Forgets the remembered value (its key leaves the settings): the option is its default again.
  void forget()
  {
    QSettings().remove(m_key);
    if (m_value == m_default)
      return;
    m_value = m_default;
    emit m_signal.changed();
  }
  SessionOption& operator=(T value)
  {
    set(std::move(value));
    return *this;
  }
  /// Calls `apply(value)` now and with every change, while `context` lives.
  template <typename Apply>
  QMetaObject::Connection follow(QObject* context, Apply apply) const
  {
    apply(m_value);
    return QObject::connect(&m_signal, &OptionSignal::changed, context, [this, apply] { apply(m_value); });
  }
  /// The change signal, for connecting as a Qt signal.
  [[nodiscard]] const OptionSignal* signal() const { return &m_signal; }

private:
  [[nodiscard]] T clamped(T value) const { return m_clamp ? m_clamp(value) : value; }

  QString m_key;
  T m_default;
  Clamp m_clamp = nullptr;
  T m_value;
  OptionSignal m_signal;
};

} // namespace mocap::ui
