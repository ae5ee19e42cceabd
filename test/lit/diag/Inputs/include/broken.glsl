float helper(float v) {
  return v * notDeclared;
}
