// SPDX-License-Identifier: Apache-2.0
#include "util/gunzip.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>

#include <zlib.h>

#include "alpha/error.hpp"

namespace molecule {
namespace {

// Owns a zlib inflate stream.
class Inflater {
public:
  explicit Inflater(const std::string& name) {
    // 16 + MAX_WBITS: expect the gzip wrapper (header, CRC-32, length).
    if (inflateInit2(&z_, 16 + MAX_WBITS) != Z_OK)
      alpha::fail(name + ": cannot start gzip decompression", alpha::ErrorKind::BadInput);
  }
  ~Inflater() { inflateEnd(&z_); }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;
  z_stream* operator->() { return &z_; }
  z_stream* get() { return &z_; }

private:
  z_stream z_{};
};

[[noreturn]] void too_large(const std::string& name, std::size_t max_bytes) {
  alpha::fail(name + ": decompresses to more than " + std::to_string(max_bytes >> 20) +
              " MiB, the limit for a structure file (a gzip bomb? --max-input-mb raises it)",
              alpha::ErrorKind::LimitExceeded);
}

// Inflates every gzip member of data, handing each chunk of output to
// sink(const char*, std::size_t); throws alpha::Error naming `name` on
// corrupt or truncated data.
template <class Sink>
void inflate_all(std::string_view data, const std::string& name, Sink sink) {
  Inflater z(name);
  char chunk[1 << 16];
  std::size_t consumed = 0;
  for (;;) {
    // zlib counts in unsigned int: feed in pieces it can take.
    z->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + consumed));
    z->avail_in = static_cast<uInt>(std::min<std::size_t>(data.size() - consumed, UINT_MAX));
    z->next_out = reinterpret_cast<Bytef*>(chunk);
    z->avail_out = sizeof chunk;
    const uInt in_before = z->avail_in;
    const int rc = inflate(z.get(), Z_NO_FLUSH);
    consumed += in_before - z->avail_in;
    sink(chunk, sizeof chunk - z->avail_out);
    if (rc == Z_STREAM_END) {
      // Another member may follow (as `cat a.gz b.gz` makes); trailing
      // zero padding is tolerated, as gzip does.
      const std::string_view rest = data.substr(consumed);
      if (std::all_of(rest.begin(), rest.end(), [](char c) { return c == '\0'; })) return;
      if (!is_gzip(rest))
        alpha::fail(name + ": corrupt gzip data (garbage after the compressed stream)", alpha::ErrorKind::BadInput);
      if (inflateReset(z.get()) != Z_OK) alpha::fail(name + ": corrupt gzip data", alpha::ErrorKind::BadInput);
      continue;
    }
    if (rc == Z_DATA_ERROR) {
      const std::string what = z->msg ? z->msg : "invalid data";
      alpha::fail(name + ": corrupt gzip data (" + what + ")", alpha::ErrorKind::BadInput);
    }
    if (rc == Z_MEM_ERROR) alpha::fail(name + ": out of memory while decompressing", alpha::ErrorKind::LimitExceeded);
    if (rc == Z_BUF_ERROR || rc == Z_NEED_DICT || rc == Z_STREAM_ERROR) {
      // No progress possible: with output space left, the input ran out.
      if (consumed == data.size())
        alpha::fail(name + ": truncated gzip data (unexpected end of file)", alpha::ErrorKind::BadInput);
      alpha::fail(name + ": corrupt gzip data", alpha::ErrorKind::BadInput);
    }
    if (consumed == data.size() && z->avail_out != 0)
      alpha::fail(name + ": truncated gzip data (unexpected end of file)", alpha::ErrorKind::BadInput);
  }
}

}  // namespace

bool is_gzip(std::string_view data) {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f && static_cast<unsigned char>(data[1]) == 0x8b;
}

std::string gunzip(std::string_view data, const std::string& name, std::size_t max_bytes) {
  if (!is_gzip(data)) alpha::fail(name + ": not gzip data (no gzip header)", alpha::ErrorKind::BadInput);
  // Counted first, the output dropped chunk by chunk: a bomb fails at the
  // limit in constant memory; then inflated again into a string of the
  // exact size (twice the time of one pass, none of the copies of growing).
  std::size_t size = 0;
  inflate_all(data, name, [&](const char*, std::size_t n) {
    if ((size += n) > max_bytes) too_large(name, max_bytes);
  });
  std::string out;
  out.reserve(size);
  inflate_all(data, name, [&](const char* chunk, std::size_t n) { out.append(chunk, n); });
  return out;
}

}  // namespace molecule
