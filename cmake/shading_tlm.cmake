# shading_tlm: the TLM-2.0 wrappers (modules/tlm, header-only) of the UA 60553 device family,
# every variant (the ROM one needs shading_ua22802's generated content); the loosely-timed mode calls
# the floor's device functions (through shading_modules).
add_library(shading_tlm INTERFACE)
target_link_libraries(shading_tlm INTERFACE shading_modules shading_ua22802)
