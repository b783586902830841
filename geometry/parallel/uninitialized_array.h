// An owning array whose elements are left uninitialised on allocation, for
// big temporaries that a parallel pass then fills whole. Their pages are
// mapped and cleared by the kernel for the threads that fill them (or that
// io::prefault them), in parallel, instead of being zeroed by the
// allocating thread first (a std::vector's resize): on the machines we
// measure, fresh memory costs about 0.5 to 3 ms per MB, more than some
// passes' arithmetic.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

namespace kappa {

template <typename T>
class UninitializedArray {
    static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>,
                  "elements must need no construction");

public:
    UninitializedArray() = default;
    explicit UninitializedArray(size_t n) : data_(new T[n]), size_(n) {}

    size_t size() const { return size_; }
    T* data() { return data_.get(); }
    const T* data() const { return data_.get(); }
    T& operator[](size_t i) { return data_[i]; }
    const T& operator[](size_t i) const { return data_[i]; }

private:
    std::unique_ptr<T[]> data_;
    size_t size_ = 0;
};

}  // namespace kappa
