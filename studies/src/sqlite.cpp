#include "sqlite.hpp"

#include <cmath>
#include <cstdio>

#include "aco/error.hpp"

namespace aco::studies::sqlite {

namespace {

// The file as an SQLite URI with its read-only parameters.
std::string read_only_uri(const std::string& file, Access access) {
  std::string uri = "file:";
  for (const char c : file) {
    if (c == '%' || c == '?' || c == '#') {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", static_cast<unsigned char>(c));
      uri += escaped;
    } else {
      uri += c;
    }
  }
  return uri + (access == Access::read_unchanging ? "?mode=ro&immutable=1" : "?mode=ro");
}

}  // namespace

Connection::Connection(const std::filesystem::path& file, Access access) : file_(file.string()) {
  const int rc = access == Access::write
                     ? sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr)
                     : sqlite3_open_v2(read_only_uri(file_, access).c_str(), &db_,
                                       SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
  if (rc != SQLITE_OK) {
    const std::string reason = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    throw Error("cannot open results database " + file_ + ": " + reason);
  }
}

void Connection::check(int rc, const std::string& doing) const {
  if (rc != SQLITE_OK && rc != SQLITE_ROW && rc != SQLITE_DONE)
    throw Error("results database " + file_ + ": " + doing + ": " + sqlite3_errmsg(db_));
}

Statement::Statement(const Connection& db, std::string sql) : db_(db), sql_(std::move(sql)) {
  db_.check(sqlite3_prepare_v3(db_.handle(), sql_.c_str(), -1, SQLITE_PREPARE_PERSISTENT, &stmt_, nullptr),
            "preparing " + sql_);
}

aco::ParamValue Statement::value(int column) const {
  switch (sqlite3_column_type(stmt_, column)) {
    case SQLITE_INTEGER:
      return integer(column);
    case SQLITE_FLOAT:
      return real(column);
    default:
      return text(column);
  }
}

TrialCell Statement::cell(int column, TrialCellType type) const {
  if (null(column)) return {};
  switch (type) {
    case TrialCellType::boolean:
      return integer(column) != 0;
    case TrialCellType::integer:
      return integer(column);
    case TrialCellType::count:
      return from_sql(integer(column));
    case TrialCellType::real:
      return real(column);
    case TrialCellType::text:
      break;
  }
  return text(column);
}

std::string Statement::shown(int column) const {
  switch (type(column)) {
    case SQLITE_NULL:
      return "NULL";
    case SQLITE_BLOB:
      return "a blob of " + std::to_string(sqlite3_column_bytes(stmt_, column)) + " bytes";
    case SQLITE_TEXT: {
      const std::string value = text(column);
      return "the text '" + (value.size() > 40 ? value.substr(0, 37) + "..." : value) + "'";
    }
    case SQLITE_FLOAT:
      return aco::to_string(aco::ParamValue(real(column)));
    default:
      return std::to_string(integer(column));
  }
}

std::string Statement::text(int column) const {
  const auto* bytes = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
  return bytes ? std::string(bytes, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
}

void Statement::bind(int i, double v) {
  db_.check(std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v), sql_);
}

Transaction::~Transaction() {
  if (!committed_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

}  // namespace aco::studies::sqlite
