// Indirect-draw helpers (Graphics.RenderPrimitivesIndirect): the command id
// of a draw and the fields of its argument record in a ByteAddressBuffer
// (16 bytes non-indexed, 20 bytes indexed). Vulkan's SV_InstanceID and
// SV_VertexID include the start instance/vertex; GetIndirect*ID removes it,
// the _Base forms keep it. unity_BaseCommandID is a material uniform.
#ifndef UNITY_INDIRECT_INCLUDED
#define UNITY_INDIRECT_INCLUDED

uint unity_BaseCommandID;
uint GetCommandID(uint svDrawID) { return unity_BaseCommandID + svDrawID; }

struct IndirectDrawArgs { uint vertexCountPerInstance; uint instanceCount; uint startVertex; uint startInstance; };
struct IndirectDrawIndexedArgs { uint indexCountPerInstance; uint instanceCount; uint startIndex; uint baseVertexIndex; uint startInstance; };

void GetIndirectDrawArgs(out IndirectDrawArgs args, ByteAddressBuffer argsBuffer, uint commandId)
{
    uint4 words = argsBuffer.Load4(commandId * 16);
    args.vertexCountPerInstance = words.x;
    args.instanceCount = words.y;
    args.startVertex = words.z;
    args.startInstance = words.w;
}
void GetIndirectDrawArgs(out IndirectDrawIndexedArgs args, ByteAddressBuffer argsBuffer, uint commandId)
{
    uint base = commandId * 20;
    uint4 words = argsBuffer.Load4(base);
    args.indexCountPerInstance = words.x;
    args.instanceCount = words.y;
    args.startIndex = words.z;
    args.baseVertexIndex = words.w;
    args.startInstance = argsBuffer.Load(base + 16);
}

uint GetIndirectInstanceCount(IndirectDrawArgs args) { return args.instanceCount; }
uint GetIndirectVertexCount(IndirectDrawArgs args) { return args.vertexCountPerInstance; }
uint GetIndirectInstanceID(IndirectDrawArgs args, uint svInstanceID) { return svInstanceID - args.startInstance; }
uint GetIndirectInstanceID_Base(IndirectDrawArgs args, uint svInstanceID) { return svInstanceID; }
uint GetIndirectVertexID(IndirectDrawArgs args, uint svVertexID) { return svVertexID - args.startVertex; }
uint GetIndirectVertexID_Base(IndirectDrawArgs args, uint svVertexID) { return svVertexID; }

uint GetIndirectInstanceCount(IndirectDrawIndexedArgs args) { return args.instanceCount; }
uint GetIndirectVertexCount(IndirectDrawIndexedArgs args) { return args.indexCountPerInstance; }
uint GetIndirectInstanceID(IndirectDrawIndexedArgs args, uint svInstanceID) { return svInstanceID - args.startInstance; }
uint GetIndirectInstanceID_Base(IndirectDrawIndexedArgs args, uint svInstanceID) { return svInstanceID; }
uint GetIndirectVertexID(IndirectDrawIndexedArgs args, uint svVertexID) { return svVertexID; }
uint GetIndirectVertexID_Base(IndirectDrawIndexedArgs args, uint svVertexID) { return svVertexID + args.startIndex; }

// With UNITY_INDIRECT_DRAW_ARGS (IndirectDrawArgs or IndirectDrawIndexedArgs):
// one record per draw, read once by InitIndirectDrawArgs.
#ifdef UNITY_INDIRECT_DRAW_ARGS
ByteAddressBuffer unity_IndirectDrawArgs;
static UNITY_INDIRECT_DRAW_ARGS globalIndirectDrawArgs;
void InitIndirectDrawArgs(uint svDrawID) { GetIndirectDrawArgs(globalIndirectDrawArgs, unity_IndirectDrawArgs, GetCommandID(svDrawID)); }
uint GetIndirectInstanceCount() { return GetIndirectInstanceCount(globalIndirectDrawArgs); }
uint GetIndirectVertexCount() { return GetIndirectVertexCount(globalIndirectDrawArgs); }
uint GetIndirectInstanceID(uint svInstanceID) { return GetIndirectInstanceID(globalIndirectDrawArgs, svInstanceID); }
uint GetIndirectInstanceID_Base(uint svInstanceID) { return GetIndirectInstanceID_Base(globalIndirectDrawArgs, svInstanceID); }
uint GetIndirectVertexID(uint svVertexID) { return GetIndirectVertexID(globalIndirectDrawArgs, svVertexID); }
uint GetIndirectVertexID_Base(uint svVertexID) { return GetIndirectVertexID_Base(globalIndirectDrawArgs, svVertexID); }
#endif

#endif // UNITY_INDIRECT_INCLUDED
