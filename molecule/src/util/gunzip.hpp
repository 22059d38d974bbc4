// SPDX-License-Identifier: Apache-2.0
// Decompression of gzip data (RFC 1952) with zlib, strictly: a truncated
// stream, corrupt data or a wrong checksum is an error, never a silently
// shortened text. Concatenated gzip members are read one after another.
#pragma once
#include <string>
#include <string_view>

namespace molecule {

// Whether data starts with the gzip magic bytes.
bool is_gzip(std::string_view data);

// The decompressed content of gzip data, inflated chunk by chunk and
// stopped as soon as it exceeds max_bytes (a gzip bomb: 1 MB can hold 1 GB
// of blanks). Throws alpha::Error with one line naming `name` when the data
// is not valid gzip or holds more than max_bytes.
std::string gunzip(std::string_view data, const std::string& name, std::size_t max_bytes);

}  // namespace molecule
