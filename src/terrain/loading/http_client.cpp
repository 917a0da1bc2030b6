#include "terrain/loading/http_client.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <ctime>

#include "terrain/sources/url_template.hpp"

#ifndef TRAILRAY_VERSION
#define TRAILRAY_VERSION "0"
#endif

namespace trailray::terrain {
namespace {

// libcurl's process-wide state: curl_global_init once (a function-local static is initialised
// exactly once even when threads race to it), and a share of DNS answers and TLS sessions. Never
// destroyed: worker threads may still clean up their handles, which use the share, at exit.
class CurlGlobal {
 public:
  static CurlGlobal& instance() {
    static CurlGlobal* global = new CurlGlobal();
    return *global;
  }
  CURLSH* share() const { return share_; }

 private:
  CurlGlobal() {
    curl_global_init(CURL_GLOBAL_DEFAULT);
    share_ = curl_share_init();
    curl_share_setopt(share_, CURLSHOPT_LOCKFUNC, &CurlGlobal::lock);
    curl_share_setopt(share_, CURLSHOPT_UNLOCKFUNC, &CurlGlobal::unlock);
    curl_share_setopt(share_, CURLSHOPT_USERDATA, this);
    curl_share_setopt(share_, CURLSHOPT_SHARE, CURL_LOCK_DATA_DNS);
    curl_share_setopt(share_, CURLSHOPT_SHARE, CURL_LOCK_DATA_SSL_SESSION);
  }
  static void lock(CURL*, curl_lock_data data, curl_lock_access, void* self) {
    static_cast<CurlGlobal*>(self)->mutexes_[static_cast<std::size_t>(data) % kLocks].lock();
  }
  static void unlock(CURL*, curl_lock_data data, void* self) {
    static_cast<CurlGlobal*>(self)->mutexes_[static_cast<std::size_t>(data) % kLocks].unlock();
  }

  static constexpr std::size_t kLocks = CURL_LOCK_DATA_LAST;
  CURLSH* share_ = nullptr;
  std::array<std::mutex, kLocks> mutexes_;
};

// One easy handle in one multi handle per thread (see the header), made on first use.
struct ThreadHandles {
  CURLM* multi = nullptr;
  CURL* easy = nullptr;

  bool ready() {
    if (multi == nullptr) multi = curl_multi_init();
    if (easy == nullptr) easy = curl_easy_init();
    return multi != nullptr && easy != nullptr;
  }
  ~ThreadHandles() {
    if (easy != nullptr) curl_easy_cleanup(easy);
    if (multi != nullptr) curl_multi_cleanup(multi);
  }
};

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r' || text.back() == '\n')) {
    text.remove_suffix(1);
  }
  return text;
}

std::optional<std::int64_t> parse_seconds(std::string_view text) {
  text = trim(text);
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
  if (text.empty() || text.size() > 12) return std::nullopt;
  std::int64_t value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    value = value * 10 + (c - '0');
  }
  return value;
}

// What one attempt collects while the transfer runs.
struct Transfer {
  StopToken stop;
  std::size_t max_body_bytes = 0;
  bool body_too_large = false;
  std::vector<unsigned char> body;
  std::vector<std::pair<std::string, std::string>> headers;  // lowercase name, value

  static size_t on_body(char* data, size_t size, size_t count, void* self) {
    auto* t = static_cast<Transfer*>(self);
    const size_t n = size * count;
    if (t->body.size() + n > t->max_body_bytes) {
      t->body_too_large = true;
      return 0;  // aborts the transfer (CURLE_WRITE_ERROR)
    }
    t->body.insert(t->body.end(), data, data + n);
    return n;
  }
  static size_t on_header(char* data, size_t size, size_t count, void* self) {
    auto* t = static_cast<Transfer*>(self);
    const std::string_view line(data, size * count);
    if (line.starts_with("HTTP/")) {
      t->headers.clear();  // a new response (after a redirect or a 100 Continue)
    } else if (const size_t colon = line.find(':'); colon != std::string_view::npos) {
      t->headers.emplace_back(lowercase(trim(line.substr(0, colon))), std::string(trim(line.substr(colon + 1))));
    }
    return size * count;
  }
  static int on_progress(void* self, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
    return static_cast<Transfer*>(self)->stop.stop_requested() ? 1 : 0;
  }

  std::string header(std::string_view name) const {
    std::string joined;
    for (const auto& [key, value] : headers) {
      if (key != name) continue;
      if (!joined.empty()) joined += ", ";
      joined += value;
    }
    return joined;
  }
};

std::optional<std::int64_t> parse_http_date(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const time_t t = curl_getdate(text.c_str(), nullptr);
  return t < 0 ? std::nullopt : std::optional<std::int64_t>(t);
}

bool is_retryable(CURLcode code) {
  switch (code) {
    case CURLE_COULDNT_RESOLVE_HOST:
    case CURLE_COULDNT_RESOLVE_PROXY:
    case CURLE_COULDNT_CONNECT:
    case CURLE_OPERATION_TIMEDOUT:
    case CURLE_SEND_ERROR:
    case CURLE_RECV_ERROR:
    case CURLE_GOT_NOTHING:
    case CURLE_PARTIAL_FILE:
    case CURLE_HTTP2:
    case CURLE_HTTP2_STREAM:
    case CURLE_SSL_CONNECT_ERROR:
      return true;
    default:
      return false;
  }
}

struct AttemptResult {
  HttpResponse response;
  bool retryable = false;
  std::optional<std::int64_t> retry_after_s;
};

AttemptResult attempt(const HttpClientOptions& options, const HttpRequest& request, curl_slist* headers,
                      const std::vector<std::string>& secrets, StopToken stop) {
  thread_local ThreadHandles handles;
  AttemptResult result;
  HttpResponse& response = result.response;
  if (!handles.ready()) {
    response.error = "cannot create a libcurl handle";
    return result;
  }
  CURL* easy = handles.easy;
  Transfer transfer;
  transfer.stop = stop;
  transfer.max_body_bytes = options.max_body_bytes;
  char error_buffer[CURL_ERROR_SIZE] = {};
  curl_easy_reset(easy);
  curl_easy_setopt(easy, CURLOPT_URL, request.url.c_str());
  curl_easy_setopt(easy, CURLOPT_SHARE, CurlGlobal::instance().share());
  curl_easy_setopt(easy, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(easy, CURLOPT_PROTOCOLS_STR, "http,https");
  curl_easy_setopt(easy, CURLOPT_REDIR_PROTOCOLS_STR, "http,https");
  curl_easy_setopt(easy, CURLOPT_FOLLOWLOCATION, 1L);
  curl_easy_setopt(easy, CURLOPT_MAXREDIRS, 5L);
  curl_easy_setopt(easy, CURLOPT_USERAGENT, http_user_agent().data());
  curl_easy_setopt(easy, CURLOPT_ACCEPT_ENCODING, "");  // whatever libcurl can decode
  curl_easy_setopt(easy, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(easy, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(options.connect_timeout.count()));
  curl_easy_setopt(easy, CURLOPT_TIMEOUT_MS, static_cast<long>(options.total_timeout.count()));
  curl_easy_setopt(easy, CURLOPT_ERRORBUFFER, error_buffer);
  curl_easy_setopt(easy, CURLOPT_WRITEFUNCTION, &Transfer::on_body);
  curl_easy_setopt(easy, CURLOPT_WRITEDATA, &transfer);
  curl_easy_setopt(easy, CURLOPT_HEADERFUNCTION, &Transfer::on_header);
  curl_easy_setopt(easy, CURLOPT_HEADERDATA, &transfer);
  curl_easy_setopt(easy, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(easy, CURLOPT_XFERINFOFUNCTION, &Transfer::on_progress);
  curl_easy_setopt(easy, CURLOPT_XFERINFODATA, &transfer);

  CURLM* multi = handles.multi;
  if (curl_multi_add_handle(multi, easy) != CURLM_OK) {
    response.error = "cannot start a libcurl transfer";
    return result;
  }
  CURLcode code = CURLE_OK;
  std::string multi_error;
  {
    std::stop_callback wake(stop, [multi] { curl_multi_wakeup(multi); });
    bool done = false;
    while (!done && !stop.stop_requested()) {
      int running = 0;
      CURLMcode mc = curl_multi_perform(multi, &running);
      int queued = 0;
      while (CURLMsg* message = curl_multi_info_read(multi, &queued)) {
        if (message->msg == CURLMSG_DONE && message->easy_handle == easy) {
          code = message->data.result;
          done = true;
        }
      }
      if (!done && mc == CURLM_OK && running == 0) mc = CURLM_INTERNAL_ERROR;  // finished without a result
      if (!done && mc == CURLM_OK) mc = curl_multi_poll(multi, nullptr, 0, 1000, nullptr);
      if (!done && mc != CURLM_OK) {
        multi_error = curl_multi_strerror(mc);
        break;
      }
    }
    response.cancelled = !done && multi_error.empty();
  }
  curl_multi_remove_handle(multi, easy);
  if (response.cancelled || code == CURLE_ABORTED_BY_CALLBACK) {
    response.cancelled = true;
    response.error = "cancelled";
    return result;
  }
  if (!multi_error.empty()) {
    response.error = "libcurl: " + multi_error;
    return result;
  }
  if (code != CURLE_OK) {
    std::string detail = error_buffer[0] != '\0' ? error_buffer : curl_easy_strerror(code);
    if (transfer.body_too_large) detail = "response larger than " + std::to_string(options.max_body_bytes) + " bytes";
    response.error = redact_secrets(std::move(detail), secrets);
    result.retryable = is_retryable(code);
    response.network_error = result.retryable;
    return result;
  }
  long status = 0;
  curl_easy_getinfo(easy, CURLINFO_RESPONSE_CODE, &status);
  response.status = static_cast<int>(status);
  response.body = std::move(transfer.body);
  response.cache_control = parse_cache_control(transfer.header("cache-control"));
  if (const std::string expires = transfer.header("expires"); !expires.empty()) {
    response.expires = parse_http_date(expires).value_or(0);
  }
  response.date = parse_http_date(transfer.header("date"));
  response.etag = transfer.header("etag");
  response.last_modified = transfer.header("last-modified");
  response.content_type = transfer.header("content-type");
  result.retryable = status == 429 || (status >= 500 && status <= 599);
  if (result.retryable) {
    const std::string retry_after = transfer.header("retry-after");
    result.retry_after_s = parse_seconds(retry_after);
    if (!result.retry_after_s) {
      if (const auto when = parse_http_date(retry_after))
        result.retry_after_s = std::max<std::int64_t>(0, *when - std::time(nullptr));
    }
  }
  return result;
}

// Sleeps for `delay`; false when `stop` was triggered first.
bool wait_for(std::chrono::milliseconds delay, StopToken stop) {
  std::mutex mutex;
  std::condition_variable_any never_notified;
  std::unique_lock lock(mutex);
  never_notified.wait_for(lock, stop, delay, [] { return false; });
  return !stop.stop_requested();
}

HttpResponse cancelled_response(int retries) {
  HttpResponse response;
  response.error = "cancelled";
  response.retries = retries;
  response.cancelled = true;
  return response;
}

}  // namespace

std::string_view http_user_agent() { return "trailray/" TRAILRAY_VERSION " (+https://github.com/trailray/trailray)"; }

RequestLimiter::RequestLimiter(int max_parallel) : max_parallel_(std::max(1, max_parallel)) {}

std::shared_ptr<RequestLimiter> RequestLimiter::process_wide() {
  static const std::shared_ptr<RequestLimiter> limiter = std::make_shared<RequestLimiter>(6);
  return limiter;
}

bool RequestLimiter::acquire(StopToken stop) {
  std::unique_lock lock(mutex_);
  if (!freed_.wait(lock, stop, [this] { return in_use_ < max_parallel_; })) return false;
  ++in_use_;
  return true;
}

void RequestLimiter::release() {
  {
    std::lock_guard lock(mutex_);
    --in_use_;
  }
  freed_.notify_one();
}

int RequestLimiter::in_use() const {
  std::lock_guard lock(mutex_);
  return in_use_;
}

CacheControl parse_cache_control(std::string_view header_value) {
  CacheControl out;
  std::size_t start = 0;
  while (start <= header_value.size()) {
    std::size_t comma = header_value.find(',', start);
    if (comma == std::string_view::npos) comma = header_value.size();
    const std::string_view directive = trim(header_value.substr(start, comma - start));
    const std::size_t equals = directive.find('=');
    const std::string name = lowercase(trim(directive.substr(0, equals)));
    if (name == "no-store") {
      out.no_store = true;
    } else if (name == "no-cache") {
      out.no_cache = true;  // with or without a field list: revalidate every time
    } else if (name == "max-age" && equals != std::string_view::npos) {
      // An unreadable max-age makes the response stale (RFC 9111 4.2.1).
      out.max_age_s = parse_seconds(directive.substr(equals + 1)).value_or(0);
    }
    start = comma + 1;
  }
  return out;
}

HttpClient::HttpClient(HttpClientOptions options) : options_(std::move(options)) {
  if (!options_.limiter) options_.limiter = RequestLimiter::process_wide();
  CurlGlobal::instance();
}

HttpResponse HttpClient::get(const HttpRequest& request, StopToken stop) const {
  HttpResponse response;
  std::vector<std::string> secrets = request.secrets;
  // The header list is built for each request: a ${VAR} reads the environment now.
  std::vector<std::string> lines;
  for (const auto& [name, value] : options_.headers) {
    ExpandedText expanded = expand_environment(value);
    if (!expanded.error.empty()) {
      response.error = "header " + name + ": " + expanded.error;
      return response;
    }
    secrets.insert(secrets.end(), expanded.secrets.begin(), expanded.secrets.end());
    lines.push_back(name + ": " + expanded.text);
  }
  if (!request.if_none_match.empty()) lines.push_back("If-None-Match: " + request.if_none_match);
  if (!request.if_modified_since.empty()) lines.push_back("If-Modified-Since: " + request.if_modified_since);
  curl_slist* headers = nullptr;
  for (const std::string& line : lines) {
    curl_slist* appended = curl_slist_append(headers, line.c_str());
    if (appended == nullptr) {
      curl_slist_free_all(headers);
      response.error = "out of memory for the request headers";
      return response;
    }
    headers = appended;
  }
  struct HeaderListOwner {
    curl_slist* list;
    ~HeaderListOwner() { curl_slist_free_all(list); }
  } owner{headers};

  std::chrono::milliseconds delay = options_.retry.first_delay;
  for (int retries = 0;; ++retries) {
    if (!options_.limiter->acquire(stop)) return cancelled_response(retries);
    AttemptResult result = attempt(options_, request, headers, secrets, stop);
    options_.limiter->release();
    result.response.retries = retries;
    if (result.response.cancelled || !result.retryable || retries >= options_.retry.max_retries) {
      return std::move(result.response);
    }
    std::chrono::milliseconds wait = std::min(delay, options_.retry.max_delay);
    if (result.retry_after_s) {
      wait = std::max(wait, std::min<std::chrono::milliseconds>(std::chrono::seconds(*result.retry_after_s),
                                                                options_.retry.max_delay));
    }
    if (!wait_for(wait, stop)) return cancelled_response(retries);
    delay = std::min(delay * 2, options_.retry.max_delay);
  }
}

}  // namespace trailray::terrain
