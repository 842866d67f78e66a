// Vulkan-Hpp's RAII layer (vulkan_raii.hpp, from Debian's libvulkan-dev): every
// handle owns itself and is destroyed in reverse order of creation, and a
// failed call throws vk::SystemError with the VkResult's name. The loader is
// opened at run time (vk::raii::Context), so a machine without libvulkan
// reports NotSupported instead of failing to start.
//
// VULKAN_HPP_NO_STRUCT_CONSTRUCTORS (set by CMake for this folder) lets the
// create-info structs be written with designated initialisers.
#pragma once

#include <vulkan/vulkan_raii.hpp>
