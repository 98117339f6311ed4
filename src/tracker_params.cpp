#include "tracker_params.hpp"

#include <type_traits>

#include "object_finder.hpp"
#include "object_model.hpp"

namespace projtrack {

template <class T, std::size_t kSize>
Opaque<T, kSize>::Opaque() {
  static_assert(sizeof(T) <= kSize, "grow Opaque's size in tracker_params.hpp");
  static_assert(alignof(T) <= alignof(std::max_align_t));
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
  new (bytes_) T();
}

template <class T, std::size_t kSize>
Opaque<T, kSize>::Opaque(const Opaque& other) {
  new (bytes_) T(other.get());
}

template <class T, std::size_t kSize>
Opaque<T, kSize>& Opaque<T, kSize>::operator=(const Opaque& other) {
  get() = other.get();
  return *this;
}

template class Opaque<ObjectModelParams, 256>;
template class Opaque<FinderParams, 256>;

}  // namespace projtrack
