#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

namespace mocap {

/// Owning, uninitialised storage for a take's per-sample arrays.
///
/// Why not Eigen's own storage: a large take's arrays are tens of MB, and faulting them in
/// 4 KB pages costs more than decoding the file. Buffers of 4 MB and more are aligned to 2 MB
/// and ask for transparent huge pages where that cannot stall (the kernel's THP defrag policy
/// `defer` or `never`), else have their pages mapped in one call (MADV_POPULATE_WRITE) instead of
/// a fault each; freed ones are kept for the next take (sample_buffer.cpp says why and by how much).
template <typename T>
class SampleBuffer
{
  static_assert(std::is_trivially_copyable_v<T>, "SampleBuffer holds plain numbers");

public:
  SampleBuffer() = default;
  /// `count` elements, contents unspecified.
  explicit SampleBuffer(std::size_t count);
  ~SampleBuffer();
  SampleBuffer(const SampleBuffer& other);
  /// Copies `other`'s elements; a buffer of the same size keeps its storage (pointers into it,
  /// such as a NumPy view of a take, stay valid), else it is replaced.
  SampleBuffer& operator=(const SampleBuffer& other);
  SampleBuffer(SampleBuffer&& other) noexcept;
  SampleBuffer& operator=(SampleBuffer&& other) noexcept;

  [[nodiscard]] T* data() { return m_data; }
  [[nodiscard]] const T* data() const { return m_data; }
  [[nodiscard]] std::size_t size() const { return m_size; }
  /// Grows or shrinks to `count` elements keeping the first min(size, count).
  void resize(std::size_t count);

private:
  T* m_data = nullptr;
  std::size_t m_size = 0;
};

/// Raw allocation behind SampleBuffer: at least `bytes` bytes, huge-page friendly when large.
void* allocateSamples(std::size_t bytes);
void freeSamples(void* data) noexcept;

template <typename T>
SampleBuffer<T>::SampleBuffer(std::size_t count)
    : m_data(static_cast<T*>(allocateSamples(count * sizeof(T)))), m_size(count)
{
}

template <typename T>
SampleBuffer<T>::~SampleBuffer()
{
  freeSamples(m_data);
}

template <typename T>
SampleBuffer<T>::SampleBuffer(const SampleBuffer& other) : SampleBuffer(other.m_size)
{
  for (std::size_t i = 0; i < m_size; ++i)
    m_data[i] = other.m_data[i];
}

template <typename T>
SampleBuffer<T>& SampleBuffer<T>::operator=(const SampleBuffer& other)
{
  if (this == &other)
    return *this;
  if (m_size == other.m_size) {  // as std::vector does: the storage stays, so pointers into it stay valid
    if (m_size > 0)
      std::memcpy(static_cast<void*>(m_data), other.m_data, m_size * sizeof(T));
    return *this;
  }
  SampleBuffer copy(other);
  *this = std::move(copy);
  return *this;
}

template <typename T>
SampleBuffer<T>::SampleBuffer(SampleBuffer&& other) noexcept : m_data(other.m_data), m_size(other.m_size)
{
  other.m_data = nullptr;
  other.m_size = 0;
}

template <typename T>
SampleBuffer<T>& SampleBuffer<T>::operator=(SampleBuffer&& other) noexcept
{
  if (this != &other) {
    freeSamples(m_data);
    m_data = other.m_data;
    m_size = other.m_size;
    other.m_data = nullptr;
    other.m_size = 0;
  }
  return *this;
}

template <typename T>
void SampleBuffer<T>::resize(std::size_t count)
{
  SampleBuffer grown(count);
  for (std::size_t i = 0; i < count && i < m_size; ++i)
    grown.m_data[i] = m_data[i];
  *this = std::move(grown);
}

} // namespace mocap
