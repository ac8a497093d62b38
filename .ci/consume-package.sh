#!/usr/bin/env bash
# Builds a throwaway console app against the packed ProximityLib (folder given as $1) and runs one query.
set -euo pipefail
feed=$1
app=$(mktemp -d)
trap 'rm -rf "$app"' EXIT
version=$(ls "$feed"/ProximityLib.*.nupkg | sed -E 's/.*ProximityLib\.(.*)\.nupkg/\1/')
cat > "$app/Consumer.csproj" <<XML
<Project Sdk="Microsoft.NET.Sdk">
  <PropertyGroup>
    <OutputType>Exe</OutputType>
    <TargetFramework>net10.0</TargetFramework>
    <RestorePackagesPath>$app/packages</RestorePackagesPath>
    <RestoreAdditionalProjectSources>$feed</RestoreAdditionalProjectSources>
  </PropertyGroup>
  <ItemGroup>
    <PackageReference Include="ProximityLib" Version="$version" />
  </ItemGroup>
</Project>
XML
cat > "$app/Program.cs" <<'CS'
using System.Numerics;
using ProximityLib;
var r = ClosestDistance.Between(new Sphere(new Vector3(0, 3, 0), 1), new Aabb3(new Vector3(-1, -1, -1), new Vector3(1, 1, 1)));
System.Console.WriteLine($"distance {r.Distance} overlaps {ProximityQuery.Overlaps(new Sphere(Vector3.Zero, 1), new Aabb3(Vector3.One, 2 * Vector3.One))}");
return r.Distance == 1f ? 0 : 1;
CS
dotnet run --project "$app/Consumer.csproj" -c Release
echo "package consumed ok (ProximityLib $version)"
