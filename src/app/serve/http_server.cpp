#include "app/serve/http_server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "app/serve/job_pool.hpp"

namespace trailray::app::serve {

HttpResponse::HttpResponse(HttpResponse&& o) noexcept
    : status(o.status),
      content_type(std::move(o.content_type)),
      headers(std::move(o.headers)),
      body(std::move(o.body)),
      file(std::exchange(o.file, -1)),
      file_size(o.file_size) {}

HttpResponse& HttpResponse::operator=(HttpResponse&& o) noexcept {
  if (this != &o) {
    if (file >= 0) ::close(file);
    status = o.status;
    content_type = std::move(o.content_type);
    headers = std::move(o.headers);
    body = std::move(o.body);
    file = std::exchange(o.file, -1);
    file_size = o.file_size;
  }
  return *this;
}

HttpResponse::~HttpResponse() {
  if (file >= 0) ::close(file);
}

HttpResponse text_response(unsigned status, std::string message) {
  HttpResponse r;
  r.status = status;
  r.body = std::move(message) + "\n";
  r.headers.emplace_back("Cache-Control", "no-store");
  return r;
}

bool is_loopback_address(std::string_view address) {
  if (address == "localhost" || address == "::1") return true;
  in_addr v4{};
  const std::string text(address);
  return inet_pton(AF_INET, text.c_str(), &v4) == 1 && (ntohl(v4.s_addr) >> 24) == 127;
}

namespace {

// Per socket (MHD's socket context): the raw target of the request being read, kept by the URI
// callback because the handler only gets the decoded one.
struct ConnectionState {
  std::string target;
};

// Per request (MHD's con_cls): the answer, made at once or by a worker while the connection waits
// suspended. Work is handed over and answers queued only once libmicrohttpd has read the whole
// request: earlier, it would close the connection after the answer instead of keeping it for the
// next request.
struct PendingAnswer {
  MHD_Connection* connection = nullptr;
  HttpResponse response;
  std::function<HttpResponse(std::stop_token)> later;  // to run, when the answer takes time
  bool queued = false;
};

struct Listener {
  int fd = -1;
  bool ipv6 = false;
};

Listener open_listener(const std::string& bind, int port) {
  const std::string address = bind == "localhost" ? "127.0.0.1" : bind;
  sockaddr_storage storage{};
  socklen_t length = 0;
  Listener l;
  if (auto* v4 = reinterpret_cast<sockaddr_in*>(&storage); inet_pton(AF_INET, address.c_str(), &v4->sin_addr) == 1) {
    v4->sin_family = AF_INET;
    v4->sin_port = htons(static_cast<std::uint16_t>(port));
    length = sizeof(sockaddr_in);
  } else if (auto* v6 = reinterpret_cast<sockaddr_in6*>(&storage);
             inet_pton(AF_INET6, address.c_str(), &v6->sin6_addr) == 1) {
    v6->sin6_family = AF_INET6;
    v6->sin6_port = htons(static_cast<std::uint16_t>(port));
    length = sizeof(sockaddr_in6);
    l.ipv6 = true;
  } else {
    throw std::runtime_error(fmt::format("--bind {}: not an IPv4 or IPv6 address (e.g. 127.0.0.1, 0.0.0.0, ::)", bind));
  }
  const std::string where = l.ipv6 ? fmt::format("[{}]:{}", address, port) : fmt::format("{}:{}", address, port);
  l.fd = ::socket(storage.ss_family, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (l.fd < 0) throw std::runtime_error(fmt::format("{}: cannot open a socket ({})", where, std::strerror(errno)));
  const int one = 1;
  ::setsockopt(l.fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(l.fd, reinterpret_cast<sockaddr*>(&storage), length) != 0 || ::listen(l.fd, SOMAXCONN) != 0) {
    const int error = errno;
    ::close(l.fd);
    throw std::runtime_error(fmt::format("{}: cannot listen ({}){}", where, std::strerror(error),
                                         error == EADDRINUSE ? "; --port 0 picks a free port" : ""));
  }
  return l;
}

int bound_port(int fd) {
  sockaddr_storage storage{};
  socklen_t length = sizeof storage;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&storage), &length) != 0) return 0;
  if (storage.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6*>(&storage)->sin6_port);
  return ntohs(reinterpret_cast<sockaddr_in*>(&storage)->sin_port);
}

// Beyond the connection limit a client is told so at once, not left waiting in the kernel's queue
// behind clients that may never finish: what it sent is read, the answer written (the socket's
// buffer is empty, so it fits), and the connection closed.
void refuse_busy(int fd) {
  char sink[4096];
  for (int i = 0; i < 16 && ::recv(fd, sink, sizeof sink, MSG_DONTWAIT) > 0; ++i) {
  }
  static const std::string kBusy = [] {
    const std::string body = "busy: too many connections; try again\n";
    return fmt::format(
        "HTTP/1.1 503 Service Unavailable\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: {}\r\n"
        "Retry-After: 1\r\nConnection: close\r\n\r\n{}",
        body.size(), body);
  }();
  [[maybe_unused]] const ssize_t sent = ::send(fd, kBusy.data(), kBusy.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
  ::shutdown(fd, SHUT_WR);
  ::close(fd);
}

MHD_Result queue_response(MHD_Connection* connection, HttpResponse&& r) {
  MHD_Response* response = nullptr;
  if (r.file >= 0) {
    response = MHD_create_response_from_fd(r.file_size, r.file);
    if (response != nullptr) r.file = -1;  // MHD closes it with the response
  } else {
    response = MHD_create_response_from_buffer(r.body.size(), r.body.data(), MHD_RESPMEM_MUST_COPY);
  }
  if (response == nullptr) return MHD_NO;
  MHD_add_response_header(response, MHD_HTTP_HEADER_CONTENT_TYPE, r.content_type.c_str());
  for (const auto& [name, value] : r.headers) MHD_add_response_header(response, name.c_str(), value.c_str());
  const MHD_Result result = MHD_queue_response(connection, r.status, response);
  MHD_destroy_response(response);
  return result;
}

}  // namespace

struct HttpServer::Impl {
  HttpHandler handler;
  std::unique_ptr<JobPool> pool;
  MHD_Daemon* daemon = nullptr;
  int port = 0;
  // Connections are accepted here, not by libmicrohttpd, which at its limit stops accepting and
  // leaves new clients waiting without a word.
  int listen_fd = -1;
  int wake_fd = -1;  // an eventfd: written to stop the acceptor
  std::thread acceptor;
  // Counted by libmicrohttpd's own notices (started, closed), which always come in pairs; a
  // connection handed over counts once the network thread has taken it, so a burst may pass the
  // limit by a few, up to libmicrohttpd's own cap.
  int max_connections = 0;
  std::atomic<int> open_connections{0};

  static void on_connection(void* cls, MHD_Connection*, void** socket_context, MHD_ConnectionNotificationCode code) {
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
      *socket_context = new ConnectionState;
      static_cast<Impl*>(cls)->open_connections.fetch_add(1);
    } else {
      delete static_cast<ConnectionState*>(*socket_context);
      *socket_context = nullptr;
      static_cast<Impl*>(cls)->open_connections.fetch_sub(1);
    }
  }

  void accept_loop() {
    pollfd fds[2] = {{listen_fd, POLLIN, 0}, {wake_fd, POLLIN, 0}};
    for (;;) {
      if (::poll(fds, 2, -1) < 0) {
        if (errno == EINTR) continue;
        return;
      }
      if (fds[1].revents != 0) return;
      for (;;) {
        sockaddr_storage address{};
        socklen_t length = sizeof address;
        const int fd =
            ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&address), &length, SOCK_NONBLOCK | SOCK_CLOEXEC);
        if (fd < 0) {
          if (errno == EINTR || errno == ECONNABORTED) continue;
          // Out of descriptors: the pending clients wait until a connection closes.
          if (errno == EMFILE || errno == ENFILE) std::this_thread::sleep_for(std::chrono::milliseconds(50));
          break;
        }
        if (open_connections.load() >= max_connections) {
          refuse_busy(fd);
          continue;
        }
        // libmicrohttpd closes the socket itself when it refuses it (the per-address limit).
        MHD_add_connection(daemon, fd, reinterpret_cast<sockaddr*>(&address), length);
      }
    }
  }

  static void* on_uri(void*, const char* uri, MHD_Connection* connection) {
    const MHD_ConnectionInfo* info = MHD_get_connection_info(connection, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    if (info != nullptr && info->socket_context != nullptr)
      static_cast<ConnectionState*>(info->socket_context)->target = uri;
    return nullptr;  // the request's con_cls stays empty until the handler sets it
  }

  static void on_completed(void*, MHD_Connection*, void** con_cls, MHD_RequestTerminationCode) {
    delete static_cast<PendingAnswer*>(*con_cls);
    *con_cls = nullptr;
  }

  static MHD_Result on_request(void* cls, MHD_Connection* connection, const char* url, const char* method, const char*,
                               const char*, std::size_t* upload_size, void** con_cls) {
    Impl& self = *static_cast<Impl*>(cls);
    if (*con_cls == nullptr) return self.first_call(connection, url, method, con_cls);
    if (*upload_size != 0) {  // a body nobody asked for: read and dropped
      *upload_size = 0;
      return MHD_YES;
    }
    auto* pending = static_cast<PendingAnswer*>(*con_cls);
    if (pending->later) return self.hand_over(*pending);
    if (pending->queued) return MHD_NO;
    pending->queued = true;
    return queue_response(connection, std::move(pending->response));
  }

  MHD_Result first_call(MHD_Connection* connection, const char* url, const char* method, void** con_cls) {
    const MHD_ConnectionInfo* info = MHD_get_connection_info(connection, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    const auto* state = info != nullptr ? static_cast<const ConnectionState*>(info->socket_context) : nullptr;
    const char* host = MHD_lookup_connection_value(connection, MHD_HEADER_KIND, MHD_HTTP_HEADER_HOST);
    const HttpRequest request{method, state != nullptr ? std::string_view(state->target) : std::string_view(url),
                              host != nullptr ? std::string_view(host) : std::string_view()};
    HttpAnswer answer;
    try {
      answer = handler(request);
    } catch (const std::exception& e) {
      answer.now = text_response(500, std::string("internal error: ") + e.what());
    }
    auto* pending = new PendingAnswer;
    pending->connection = connection;
    *con_cls = pending;
    if (answer.now || !answer.later)
      pending->response = answer.now ? std::move(*answer.now) : text_response(500, "no answer");
    else
      pending->later = std::move(answer.later);
    return MHD_YES;
  }

  // The work to a worker while the connection waits, suspended; the worker's resume brings the
  // connection back here with the answer ready.
  MHD_Result hand_over(PendingAnswer& pending) {
    auto later = std::move(pending.later);
    pending.later = nullptr;
    // Suspended before the job can run, so its resume always follows the suspend.
    MHD_suspend_connection(pending.connection);
    PendingAnswer* p = &pending;
    const bool taken = pool->submit([p, later = std::move(later)](std::stop_token stop) {
      try {
        p->response = later(stop);
      } catch (const std::exception& e) {
        p->response = text_response(500, std::string("internal error: ") + e.what());
      }
      MHD_resume_connection(p->connection);
    });
    if (!taken) {
      pending.response = text_response(503, "busy: too many answers waiting; try again");
      pending.response.headers.emplace_back("Retry-After", "1");
      MHD_resume_connection(pending.connection);
    }
    return MHD_YES;
  }
};

HttpServer::HttpServer(const HttpServerOptions& o, HttpHandler handler) : impl_(std::make_unique<Impl>()) {
  Impl& self = *impl_;
  self.handler = std::move(handler);
  self.max_connections = static_cast<int>(std::min(o.max_connections, 1u << 30));
  const Listener listener = open_listener(o.bind, o.port);
  self.listen_fd = listener.fd;
  self.port = bound_port(listener.fd);
  self.wake_fd = ::eventfd(0, EFD_CLOEXEC);
  self.pool = std::make_unique<JobPool>(o.workers, o.max_queued);
  // libmicrohttpd's own limit is a hard cap above ours (the acceptor refuses first; a burst may pass ours by a few).
  const unsigned flags =
      MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL | MHD_ALLOW_SUSPEND_RESUME | MHD_USE_NO_LISTEN_SOCKET;
  self.daemon = MHD_start_daemon(flags, 0, nullptr, nullptr, &Impl::on_request, &self, MHD_OPTION_CONNECTION_LIMIT,
                                 o.max_connections + 64, MHD_OPTION_PER_IP_CONNECTION_LIMIT,
                                 o.max_connections_per_address, MHD_OPTION_CONNECTION_TIMEOUT, o.idle_timeout_s,
                                 MHD_OPTION_CONNECTION_MEMORY_LIMIT, o.connection_memory, MHD_OPTION_NOTIFY_CONNECTION,
                                 &Impl::on_connection, &self, MHD_OPTION_URI_LOG_CALLBACK, &Impl::on_uri, nullptr,
                                 MHD_OPTION_NOTIFY_COMPLETED, &Impl::on_completed, nullptr, MHD_OPTION_END);
  if (self.daemon == nullptr || self.wake_fd < 0) {
    ::close(listener.fd);
    if (self.wake_fd >= 0) ::close(self.wake_fd);
    if (self.daemon != nullptr) MHD_stop_daemon(self.daemon);
    self.pool->shutdown();
    throw std::runtime_error(fmt::format("{}:{}: the HTTP server (libmicrohttpd) did not start", o.bind, o.port));
  }
  self.acceptor = std::thread([&self] { self.accept_loop(); });
}

HttpServer::~HttpServer() {
  Impl& self = *impl_;
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t written = ::write(self.wake_fd, &one, sizeof one);
  self.acceptor.join();
  ::close(self.listen_fd);
  ::close(self.wake_fd);
  // Every suspended connection answered (the workers stop early) and resumed before the daemon
  // stops: libmicrohttpd must not be stopped with a connection suspended.
  self.pool->shutdown();
  MHD_stop_daemon(self.daemon);
}

int HttpServer::port() const { return impl_->port; }

}  // namespace trailray::app::serve
