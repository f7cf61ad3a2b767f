#include "commands.h"
#include "table.h"

#include "core/errors.h"
#include "core/format.h"

#include <iostream> // for std::cout

namespace meshpaint::cli {

int devices_command(const Argv& argv)
{
  Args args("devices", argv, {}, {});
  args.expect_positionals(0, 0, "");
  Table table({"P:D", "device", "platform", "type", "memory", "max alloc", "images", "default"});
  // The device a command would use; none is marked if MESHPAINT_DEVICE
  // matches nothing, which is what this listing helps to fix.
  int chosen_platform = -1, chosen_device = -1;
  try {
    const DeviceInfo chosen = Runtime::open()->info();
    chosen_platform = chosen.platform_index;
    chosen_device = chosen.device_index;
  } catch (const DeviceError&) {
  }
  for (const DeviceInfo& d : Runtime::list_devices())
    table.add({std::to_string(d.platform_index) + ":" + std::to_string(d.device_index), d.name, d.platform,
               d.gpu ? "GPU" : "CPU", format_bytes(d.global_memory), format_bytes(d.max_allocation),
               d.images ? std::to_string(d.image_max_width) + "x" + std::to_string(d.image_max_height) : "no",
               d.platform_index == chosen_platform && d.device_index == chosen_device ? "*" : ""});
  table.print(std::cout);
  return 0;
}

} // namespace meshpaint::cli
