#include "sqlite.hpp"

#include <cmath>

#include "aco/error.hpp"

namespace aco::studies::sqlite {

Connection::Connection(const std::filesystem::path& file) : file_(file.string()) {
  const int rc = sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
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
