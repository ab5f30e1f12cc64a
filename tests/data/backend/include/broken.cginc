// A helper with a type error on line 4.
fixed4 Broken()
{
    float2 v = float2(1, 2).xyz;
    return fixed4(v, 0, 1);
}
