// Helpers for the mesh I/O tests: building binary files byte by byte and
// checking MeshLoadError messages.
#pragma once

#include "geometry/io/mesh_io.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>

namespace kappa::test {

// Appends values in a chosen byte order: Bytes().text("ply\n").le<float>(1).be<int>(2)
class Bytes {
public:
    Bytes& text(const std::string& s) {
        data_ += s;
        return *this;
    }
    template <typename T>
    Bytes& le(T value) {
        return put(value, false);
    }
    template <typename T>
    Bytes& be(T value) {
        return put(value, true);
    }
    const std::string& str() const { return data_; }

private:
    template <typename T>
    Bytes& put(T value, bool big_endian) {
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        bool host_little = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
        if (big_endian == host_little)
            for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
        data_.append(b, sizeof(T));
        return *this;
    }
    std::string data_;
};

// Runs `load`, which must throw MeshLoadError; returns what().
inline std::string load_error(const std::function<void()>& load) {
    try {
        load();
    } catch (const MeshLoadError& e) {
        return e.what();
    }
    FAIL("expected a MeshLoadError");
    return {};
}

// The message is one line "NAME: problem" mentioning `fragment`.
#define REQUIRE_LOAD_ERROR(expression, name, fragment)                                 \
    do {                                                                               \
        std::string message_ = ::kappa::test::load_error([&] { (void)(expression); }); \
        INFO("message: " << message_);                                                 \
        CHECK(message_.rfind(std::string(name) + ": ", 0) == 0);                       \
        CHECK(message_.find('\n') == std::string::npos);                               \
        CHECK(message_.find(fragment) != std::string::npos);                           \
    } while (0)

// Reading helpers on in-memory text.
inline Mesh ply_from(const std::string& s) { return read_ply(s.data(), s.size(), "test.ply"); }
inline Mesh off_from(const std::string& s) { return read_off(s.data(), s.size(), "test.off"); }
inline Mesh obj_from(const std::string& s) { return read_obj(s.data(), s.size(), "test.obj"); }
inline Mesh stl_from(const std::string& s) { return read_stl(s.data(), s.size(), "test.stl"); }

}  // namespace kappa::test
