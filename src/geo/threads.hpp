#pragma once
// Whether this build can start threads. Native builds can. A WebAssembly build can only when
// compiled with pthreads, which the browser allows only on pages served with COOP/COEP headers:
// the page is built without, and there std::thread's constructor throws. Code that splits work
// across threads asks here first and otherwise does it all on the calling thread.

namespace trailray::geo {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kThreadsAvailable = false;
#else
inline constexpr bool kThreadsAvailable = true;
#endif

}  // namespace trailray::geo
