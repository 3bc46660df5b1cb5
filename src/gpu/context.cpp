#include "gpu/context.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "base/closest_word.hpp"

namespace tp::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

vk::DebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
  using S = vk::DebugUtilsMessageSeverityFlagBitsEXT;
  using T = vk::DebugUtilsMessageTypeFlagBitsEXT;
  return vk::DebugUtilsMessengerCreateInfoEXT{
      .messageSeverity = S::eWarning | S::eError,
      .messageType = T::eGeneral | T::eValidation | T::ePerformance,
      .pfnUserCallback = validationCallback,
      .pUserData = log,
  };
}

bool hasLayer(const vk::raii::Context& context, const char* name) {
  for (const auto& layer : context.enumerateInstanceLayerProperties()) {
    if (std::string(layer.layerName.data()) == name) return true;
  }
  return false;
}

// The folders the Linux loader searches for driver manifests when neither
// VK_DRIVER_FILES nor VK_ICD_FILENAMES is set (it also reads $XDG_* ones).
constexpr const char* kDriverFolders[] = {"/etc/vulkan/icd.d", "/usr/local/share/vulkan/icd.d",
                                          "/usr/share/vulkan/icd.d"};

// What the loader looked for when it found no driver, and how to point it at
// one, in one line: the environment variable it read, or the folders it
// searched; and the driver manifests those folders hold.
std::string noDriverMessage() {
  std::vector<std::string> manifests;
  for (const char* folder : kDriverFolders) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
      if (entry.path().extension() == ".json") manifests.push_back(entry.path().string());
    }
  }
  std::sort(manifests.begin(), manifests.end());
  const std::string install =
      "install one (Debian: apt-get install mesa-vulkan-drivers gives lavapipe, which needs "
      "no GPU)";
  const std::string device = ", and choose among its devices with --device NAME";
  // VK_DRIVER_FILES is the newer name; the loader reads it first.
  for (const char* variable : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"}) {
    if (const char* value = std::getenv(variable); value && *value) {
      const std::string to = manifests.empty() ? "; " + install + " and set it to its .json or unset it"
                                               : "; set it to an installed driver's .json (" +
                                                     base::listWords(manifests) + ") or unset it";
      return std::string("no Vulkan driver: the loader found none it could load in ") + variable + "=" + value + to +
             device;
    }
  }
  const std::vector<std::string> folders(std::begin(kDriverFolders), std::end(kDriverFolders));
  const std::string there = manifests.empty() ? "" : " (there: " + base::listWords(manifests) + ")";
  return "no Vulkan driver: the loader found none it could load in " + base::listWords(folders) + there + "; " +
         install + " or point VK_ICD_FILENAMES at a driver's .json" + device;
}

vk::raii::Instance createInstance(const vk::raii::Context& context, const ContextOptions& options, ValidationLog* log) {
  if (context.enumerateInstanceVersion() < VK_API_VERSION_1_3) {
    throw std::runtime_error("the Vulkan loader is older than 1.3; tidepool needs Vulkan 1.3");
  }
  vk::ApplicationInfo app{.pApplicationName = "tidepool", .apiVersion = VK_API_VERSION_1_3};
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (options.validation) {
    if (!hasLayer(context, kValidationLayer)) {
      throw std::runtime_error(std::string("validation was requested but ") + kValidationLayer +
                               " is not installed (Debian: apt-get install vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  const auto available = context.enumerateInstanceExtensionProperties();
  for (const std::string& name : options.surfaceExtensions) {
    const bool found = std::any_of(available.begin(), available.end(),
                                   [&](const vk::ExtensionProperties& e) { return name == e.extensionName.data(); });
    if (!found) throw std::runtime_error("the Vulkan loader has no " + name + ", which a window's surface needs");
    extensions.push_back(name.c_str());
  }
  static constexpr vk::ValidationFeatureEnableEXT enables[] = {
      vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  vk::StructureChain<vk::InstanceCreateInfo, vk::ValidationFeaturesEXT, vk::DebugUtilsMessengerCreateInfoEXT> chain{
      vk::InstanceCreateInfo{
          .pApplicationInfo = &app,
          .enabledLayerCount = uint32_t(layers.size()),
          .ppEnabledLayerNames = layers.data(),
          .enabledExtensionCount = uint32_t(extensions.size()),
          .ppEnabledExtensionNames = extensions.data(),
      },
      vk::ValidationFeaturesEXT{.enabledValidationFeatureCount = 1, .pEnabledValidationFeatures = enables},
      messengerInfo(log),
  };
  if (!options.validation) {
    chain.unlink<vk::ValidationFeaturesEXT>();
    chain.unlink<vk::DebugUtilsMessengerCreateInfoEXT>();
  }
  try {
    return vk::raii::Instance(context, chain.get<vk::InstanceCreateInfo>());
  } catch (const vk::IncompatibleDriverError&) {
    throw std::runtime_error(noDriverMessage());
  }
}

int typeRank(vk::PhysicalDeviceType type) {
  switch (type) {
    case vk::PhysicalDeviceType::eDiscreteGpu:
      return 0;
    case vk::PhysicalDeviceType::eIntegratedGpu:
      return 1;
    case vk::PhysicalDeviceType::eVirtualGpu:
      return 2;
    case vk::PhysicalDeviceType::eCpu:
      return 3;
    default:
      return 4;
  }
}

std::optional<uint32_t> universalQueueFamily(const vk::raii::PhysicalDevice& device) {
  auto families = device.getQueueFamilyProperties();
  for (uint32_t i = 0; i < families.size(); ++i) {
    auto flags = families[i].queueFlags;
    if ((flags & vk::QueueFlagBits::eGraphics) && (flags & vk::QueueFlagBits::eCompute)) return i;
  }
  return std::nullopt;
}

bool usable(const vk::raii::PhysicalDevice& device) {
  return device.getProperties().apiVersion >= VK_API_VERSION_1_3 && universalQueueFamily(device);
}

vk::raii::PhysicalDevice choosePhysicalDevice(const vk::raii::Instance& instance, std::string wanted) {
  if (wanted.empty()) {
    if (const char* env = std::getenv("TIDEPOOL_DEVICE")) wanted = env;
  }
  vk::raii::PhysicalDevices devices(instance);
  std::string names;
  std::optional<size_t> best;
  for (size_t i = 0; i < devices.size(); ++i) {
    auto props = devices[i].getProperties();
    std::string name = props.deviceName.data();
    names += (names.empty() ? "" : ", ") + name;
    if (!usable(devices[i])) continue;
    if (!wanted.empty()) {
      if (name.find(wanted) != std::string::npos) return std::move(devices[i]);
      continue;
    }
    if (!best || typeRank(props.deviceType) < typeRank(devices[*best].getProperties().deviceType)) best = i;
  }
  if (!wanted.empty()) {
    throw std::runtime_error("no usable Vulkan 1.3 device matches '" + wanted +
                             "' (devices: " + (names.empty() ? "none" : names) + ")");
  }
  if (!best) {
    throw std::runtime_error(
        "no Vulkan 1.3 device with a graphics+compute queue (devices: " + (names.empty() ? "none" : names) +
        "); on a machine without a GPU install mesa-vulkan-drivers for lavapipe");
  }
  return std::move(devices[*best]);
}

bool hasDeviceExtension(const vk::raii::PhysicalDevice& device, const char* name) {
  for (const auto& e : device.enumerateDeviceExtensionProperties()) {
    if (std::string(e.extensionName.data()) == name) return true;
  }
  return false;
}

vk::raii::Device createDevice(const vk::raii::PhysicalDevice& physical, uint32_t family, bool swapchain) {
  std::vector<const char*> extensions;
  if (swapchain) {
    if (!hasDeviceExtension(physical, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
      throw std::runtime_error(std::string(physical.getProperties().deviceName.data()) + " has no " +
                               VK_KHR_SWAPCHAIN_EXTENSION_NAME + ": it cannot show a window");
    }
    extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  }
  float priority = 1.0f;
  vk::DeviceQueueCreateInfo queueInfo{.queueFamilyIndex = family, .queueCount = 1, .pQueuePriorities = &priority};
  vk::StructureChain<vk::DeviceCreateInfo, vk::PhysicalDeviceFeatures2, vk::PhysicalDeviceVulkan12Features,
                     vk::PhysicalDeviceVulkan13Features>
      chain{
          vk::DeviceCreateInfo{
              .queueCreateInfoCount = 1,
              .pQueueCreateInfos = &queueInfo,
              .enabledExtensionCount = uint32_t(extensions.size()),
              .ppEnabledExtensionNames = extensions.data(),
          },
          // The deferred water's G-buffer pass tags its tiles from the fragment stage.
          vk::PhysicalDeviceFeatures2{.features = {.fragmentStoresAndAtomics = VK_TRUE}},
          vk::PhysicalDeviceVulkan12Features{.hostQueryReset = VK_TRUE},
          // maintenance4: glslang's SPIR-V 1.6 declares compute local sizes with LocalSizeId.
          vk::PhysicalDeviceVulkan13Features{
              .synchronization2 = VK_TRUE, .dynamicRendering = VK_TRUE, .maintenance4 = VK_TRUE},
      };
  return vk::raii::Device(physical, chain.get<vk::DeviceCreateInfo>());
}

}  // namespace

Context::Context(const ContextOptions& options)
    : log_(std::make_unique<ValidationLog>()),
      instance_(createInstance(context_, options, log_.get())),
      messenger_(options.validation ? std::optional<vk::raii::DebugUtilsMessengerEXT>(std::in_place, instance_,
                                                                                      messengerInfo(log_.get()))
                                    : std::nullopt),
      physical_(choosePhysicalDevice(instance_, options.deviceName)),
      properties_(physical_.getProperties()),
      memoryProperties_(physical_.getMemoryProperties()),
      queueFamily_(*universalQueueFamily(physical_)),
      timestampValidBits_(physical_.getQueueFamilyProperties()[queueFamily_].timestampValidBits),
      device_(createDevice(physical_, queueFamily_, options.swapchain)),
      queue_(device_, queueFamily_, 0),
      commandPool_(device_, vk::CommandPoolCreateInfo{.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                      .queueFamilyIndex = queueFamily_}) {}

}  // namespace tp::gpu
