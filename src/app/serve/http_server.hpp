#pragma once
// An HTTP/1.1 server for `trailray serve` over GNU libmicrohttpd: one network thread polls every
// connection with epoll and never blocks on a client (a slow or silent client holds a socket, not
// a thread), with a cap on connections (per address too), an idle timeout and a per-connection
// memory cap (a request whose header does not fit is answered with an error and closed). The
// handler runs on the network thread and must be quick; an answer that takes time is handed to
// a JobPool while its connection waits, suspended, without holding the thread.
// It knows nothing of trailray: requests in, responses out.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace trailray::app::serve {

struct HttpRequest {
  std::string_view method;
  std::string_view target;  // as sent: not decoded, with its query
  std::string_view host;    // the Host header; empty when absent
};

struct HttpResponse {
  unsigned status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;  // unless `file` is set
  // A file to send whole (owned: closed by the server), of `file_size` bytes.
  int file = -1;
  std::uint64_t file_size = 0;

  HttpResponse() = default;
  HttpResponse(HttpResponse&& other) noexcept;
  HttpResponse& operator=(HttpResponse&& other) noexcept;
  HttpResponse(const HttpResponse&) = delete;
  HttpResponse& operator=(const HttpResponse&) = delete;
  ~HttpResponse();
};

// A plain-text answer: `status` with `message` and a newline.
HttpResponse text_response(unsigned status, std::string message);

// What the handler makes of a request: an answer now, or work whose answer comes later.
struct HttpAnswer {
  std::optional<HttpResponse> now;
  std::function<HttpResponse(std::stop_token)> later;  // run on the job pool
};

using HttpHandler = std::function<HttpAnswer(const HttpRequest&)>;

struct HttpServerOptions {
  std::string bind = "127.0.0.1";  // an IPv4 or IPv6 address, or localhost
  int port = 0;                    // 0: a free port
  unsigned max_connections = 256;
  unsigned max_connections_per_address = 0;  // 0: no limit
  unsigned idle_timeout_s = 30;
  std::size_t connection_memory = 32 * 1024;  // bytes per connection, the request's header included
  unsigned workers = 4;                       // JobPool threads
  std::size_t max_queued = 512;               // answers waiting for a worker, beyond it 503
};

class HttpServer {
 public:
  // Listens at once. Throws std::runtime_error naming the address ("127.0.0.1:8123: Address already
  // in use") when it cannot.
  HttpServer(const HttpServerOptions& options, HttpHandler handler);
  ~HttpServer();  // stops: pending answers finish (asked to stop), then the connections close
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  int port() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

// Whether an address as given to --bind is a loopback one (127.0.0.0/8, ::1, localhost).
bool is_loopback_address(std::string_view address);

}  // namespace trailray::app::serve
