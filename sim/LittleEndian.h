#pragma once

// Numbers in the byte strings of the sheet and recording files: little-endian integers,
// and doubles bit for bit as their 64-bit patterns.

#include <QByteArray>
#include <QtEndian>
#include <bit>
#include <cstdint>

namespace pf::le {

template <typename T> void put(QByteArray& out, T v) {
    char b[sizeof(T)];
    qToLittleEndian(v, b);
    out.append(b, sizeof(T));
}

inline void putF64(QByteArray& out, double v) {
    put(out, std::bit_cast<std::uint64_t>(v));
}

template <typename T> T take(const char* p) {
    return qFromLittleEndian<T>(p);
}

inline double takeF64(const char* p) {
    return std::bit_cast<double>(take<std::uint64_t>(p));
}

} // namespace pf::le
