// SPDX-License-Identifier: Apache-2.0
// Content checksums: SHA-256 (Debian's nettle), as 64 hex digits. Batch
// runs know by it whether an input changed since it was analysed.
#pragma once
#include <string>
#include <string_view>

namespace molecule {

std::string sha256_hex(std::string_view data);

}  // namespace molecule
