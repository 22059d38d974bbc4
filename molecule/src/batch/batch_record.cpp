// SPDX-License-Identifier: Apache-2.0
#include "batch/batch_record.hpp"

#include <exception>

#include "alpha/error.hpp"
#include "util/checksum.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;

}  // namespace

std::string record_line(const BatchRecord& r) {
  const json line = {{"id", r.id},         {"path", r.path},         {"checksum", r.checksum},
                     {"key", r.key},       {"status", r.status},     {"category", r.category},
                     {"message", r.message}, {"seconds", r.seconds}, {"rows", r.rows}};
  return line.dump(-1, ' ', false, json::error_handler_t::replace);
}

BatchRecord parse_record(std::string_view line) {
  try {
    const json j = json::parse(line);
    BatchRecord r;
    r.id = j.at("id");
    r.path = j.at("path");
    r.checksum = j.at("checksum");
    r.key = j.at("key");
    r.status = j.at("status");
    r.category = j.at("category");
    r.message = j.at("message");
    r.seconds = j.at("seconds");
    r.rows = j.at("rows");
    if (r.id.empty() || (r.status == "ok") == r.rows.is_null())
      alpha::fail("inconsistent record", alpha::ErrorKind::BadInput);
    return r;
  } catch (const std::exception& e) {
    alpha::fail(std::string("malformed record: ") + e.what(), alpha::ErrorKind::BadInput);
  }
}

std::string batch_key(const json& parameters, const std::string& version) {
  return sha256_hex(json{{"version", version}, {"parameters", parameters}}.dump()).substr(0, 16);
}

}  // namespace molecule
