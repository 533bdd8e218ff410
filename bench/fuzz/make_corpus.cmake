# Assembles the fuzz seed corpora and the scene harness's root in the build folder, from the repository's own
# files (run with cmake -P at build time; nothing large is committed):
#   corpus/scene/    scenes/*.scene + bench/fuzz/seeds/scene/*
#   corpus/csg/      every *.csg under scenes/ + seeds/csg/*
#   corpus/obj/      scenes/assets/*.obj of at most MAX_SEED_BYTES (bunny.obj when generated) + seeds/obj/*
#   corpus/texture/  scenes/assets/* images of at most MAX_SEED_BYTES + tiny images of every accepted format
#                    (TEXTURE_SEEDS, written by make_texture_seeds) + seeds/texture/*
#   scene_root/      what the seed scenes name, small: every scenes/*.csg, assets/bunny.obj and assets/head.obj
#                    as tiny meshes, assets/head_*.png as a 4 × 3 PNG, assets/sky.exr and assets/sky.png (the
#                    environment maps of seeds/scene/path_*.scene) as tiny images
# Inputs: SOURCE_DIR (the repository), OUT_DIR (bench/fuzz in the build), TEXTURE_SEEDS (a folder).
foreach(var SOURCE_DIR OUT_DIR TEXTURE_SEEDS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "make_corpus.cmake: ${var} is not set")
  endif()
endforeach()
set(MAX_SEED_BYTES 131072)
set(SEEDS ${SOURCE_DIR}/bench/fuzz/seeds)
set(CORPUS ${OUT_DIR}/corpus)
set(ROOT ${OUT_DIR}/scene_root)
file(REMOVE_RECURSE ${CORPUS} ${ROOT})
file(MAKE_DIRECTORY ${CORPUS}/scene ${CORPUS}/csg ${CORPUS}/obj ${CORPUS}/texture ${ROOT}/assets)

function(copy_small dest)
  foreach(f ${ARGN})
    file(SIZE ${f} size)
    if(size LESS_EQUAL ${MAX_SEED_BYTES})
      file(COPY ${f} DESTINATION ${dest})
    endif()
  endforeach()
endfunction()

file(GLOB scene_files ${SOURCE_DIR}/scenes/*.scene ${SEEDS}/scene/*)
copy_small(${CORPUS}/scene ${scene_files})
file(GLOB_RECURSE csg_files ${SOURCE_DIR}/scenes/*.csg)
file(GLOB csg_seeds ${SEEDS}/csg/*)
copy_small(${CORPUS}/csg ${csg_files} ${csg_seeds})
file(GLOB obj_files ${SOURCE_DIR}/scenes/assets/*.obj ${SEEDS}/obj/*)
copy_small(${CORPUS}/obj ${obj_files})
file(GLOB image_files ${SOURCE_DIR}/scenes/assets/*.png ${SOURCE_DIR}/scenes/assets/*.jpg
     ${SOURCE_DIR}/scenes/assets/*.exr ${SOURCE_DIR}/scenes/assets/*.hdr ${TEXTURE_SEEDS}/* ${SEEDS}/texture/*)
copy_small(${CORPUS}/texture ${image_files})

if(csg_files)
  file(COPY ${csg_files} DESTINATION ${ROOT})
endif()
configure_file(${SEEDS}/obj/tetra_negative.obj ${ROOT}/assets/bunny.obj COPYONLY)
configure_file(${SEEDS}/obj/cube_all_attributes.obj ${ROOT}/assets/head.obj COPYONLY)
configure_file(${TEXTURE_SEEDS}/rgb.png ${ROOT}/assets/head_diffuse.png COPYONLY)
configure_file(${TEXTURE_SEEDS}/rgb.png ${ROOT}/assets/head_normal.png COPYONLY)
# The environment maps the SPEC §7 seeds name: a float image and an 8-bit one.
configure_file(${TEXTURE_SEEDS}/zip.exr ${ROOT}/assets/sky.exr COPYONLY)
configure_file(${TEXTURE_SEEDS}/rgb.png ${ROOT}/assets/sky.png COPYONLY)

foreach(h scene csg obj texture)
  file(GLOB got ${CORPUS}/${h}/*)
  list(LENGTH got n)
  if(n EQUAL 0)
    message(FATAL_ERROR "make_corpus.cmake: the ${h} corpus is empty")
  endif()
endforeach()
