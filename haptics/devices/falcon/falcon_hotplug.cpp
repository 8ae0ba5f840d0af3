#include "haptics/devices/falcon/falcon_hotplug.hpp"

#include <libusb.h>

#include "haptics/devices/falcon/falcon_protocol.hpp"

namespace needle::haptics::falcon {
namespace {

int LIBUSB_CALL on_event(libusb_context*, libusb_device*, libusb_hotplug_event event, void* counts) {
  auto* c = static_cast<FalconHotplug::Counts*>(counts);
  if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED) c->arrivals.fetch_add(1);
  if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT) c->departures.fetch_add(1);
  return 0;  // keep the callback registered
}

}  // namespace

FalconHotplug::FalconHotplug() {
  if (const int rc = libusb_init(&context_); rc != 0) {
    context_ = nullptr;
    reason_ = std::string("libusb_init failed: ") + libusb_error_name(rc);
    return;
  }
  if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
    reason_ = "this libusb has no hotplug support";
    return;
  }
  const int rc = libusb_hotplug_register_callback(
      context_,
      static_cast<libusb_hotplug_event>(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED | LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
      LIBUSB_HOTPLUG_ENUMERATE, kVendorId, kProductId, LIBUSB_HOTPLUG_MATCH_ANY, on_event, &counts_, &handle_);
  if (rc != LIBUSB_SUCCESS) {
    reason_ = std::string("hotplug registration failed: ") + libusb_error_name(rc);
    return;
  }
  supported_ = true;
  thread_ = std::thread([this] {
    while (!stop_.load()) {
      timeval tv{0, 100000};
      libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    }
  });
}

FalconHotplug::~FalconHotplug() {
  if (supported_) {
    stop_ = true;
    // Deregistering wakes the event thread, which then sees stop_.
    libusb_hotplug_deregister_callback(context_, handle_);
    thread_.join();
  }
  if (context_ != nullptr) libusb_exit(context_);
}

}  // namespace needle::haptics::falcon
