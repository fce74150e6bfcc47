// attack: includes a world-readable file outside the framework with a digraph (%:include), which a
// line-based check for "#include" does not see; the compiler's diagnostics would quote its text
// base: reference  expect: 0
%:include "@LEAK@"
