# proxy-gen's scene mode: an unusable --cache folder fails before any work with exit 3 and one
# line naming it (the dragon's wrap would take many seconds: the short TIMEOUT is part of the
# assertion); --cache with --no-cache is a usage error; a "make_proxy" that is not a boolean is
# refused at load, naming the scene file and the JSON path. Corpus: corpus_proxygen.py.
set(pg @CORPUS@/proxygen)
set(pg_scene @DATA@/../scenes/dragon-plane.json)
set(pg_slow_wrap "--kind outside --alpha 0.004 --offset 0.0005")

bad_input_test(proxygen_cache_is_a_file proxy-gen
  "${pg_scene} ${pg_slow_wrap} --out-dir @OUT@/proxies --cache ${pg}/a_file"
  CODE 3 REGEX "a_file: cannot use the proxy cache folder" INPUTS ${pg}/a_file WATCH ${pg}
  TIMEOUT 3)
bad_input_test(proxygen_cache_below_a_file proxy-gen
  "${pg_scene} ${pg_slow_wrap} --out-dir @OUT@/proxies --cache ${pg}/a_file/cache"
  CODE 3 REGEX "a_file/cache: cannot use the proxy cache folder" INPUTS ${pg}/a_file WATCH ${pg}
  TIMEOUT 3)
bad_input_test(proxygen_cache_and_no_cache proxy-gen
  "${pg_scene} --out-dir @OUT@/proxies --cache @OUT@/cache --no-cache"
  REGEX "--no-cache|--cache" INPUTS ${pg_scene} TIMEOUT 3)
foreach(type string number null)
  bad_input_test(proxygen_make_proxy_${type} proxy-gen
    "${pg}/make_proxy_${type}.json --out-dir @OUT@/proxies --cache @OUT@/cache"
    REGEX "make_proxy_${type}.json: meshes\\[0\\]\\.make_proxy" INPUTS ${pg}/make_proxy_${type}.json
    WATCH ${pg})
endforeach()
