# An inside proxy needs a surface that bounds a volume (every welded edge with an even number of
# faces). A surface with odd edges and no boundary (corpus_guarantee.py) was refused with advice
# that could not work (--fill-holes); now the one error line names the odd edges and advises
# --kind outside or general, and nothing is written.
foreach(method wrap erode)
  bad_input_test(guarantee_theta_inside_${method} proxy-gen
    "@CORPUS@/guarantee_theta.off --kind inside --method ${method} -o @OUT@/p.ply --json @OUT@/p.json"
    REGEX "guarantee_theta.off: 3 edges with an odd number .*--kind outside or --kind general"
    INPUTS @CORPUS@/guarantee_theta.off TIMEOUT 30)
endforeach()
